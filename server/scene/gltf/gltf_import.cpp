#include "scene/gltf/gltf_import.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "bundle_paths/bundle_path.h"
#include "bundle_paths/statement_names.h"
#include "scene/gltf/data_uri.h"
#include "scene/gltf/gltf_accessor.h"
#include "scene/gltf/gltf_container.h"
#include "scene/gltf/gltf_draco.h"
#include "scene/gltf/gltf_json.h"
#include "scene/gltf/gltf_meshopt.h"
#include "scene/gltf/gltf_rig.h"
#include "scene/reading/image_lookup.h"
#include "scene/reading/import_error.h"
#include "scene/reading/mesh_builder.h"
#include "scene/reading/texture_decode.h"

namespace toond::scene {
namespace {

using namespace gltf_json;

// Extensions whose meaning the importer reads; a file that requires any
// other is refused by name.
constexpr std::array<std::string_view, 6> kReadExtensions = {
    "KHR_mesh_quantization", "KHR_texture_transform",   "EXT_texture_webp",
    "KHR_materials_unlit",   "EXT_meshopt_compression", "KHR_draco_mesh_compression",
};

bool reads_extension(std::string_view name) {
  return std::find(kReadExtensions.begin(), kReadExtensions.end(), name) != kReadExtensions.end();
}

// Whether `uri` starts with a scheme ("http:", "file:"); a single letter
// before the colon is a drive letter, which is refused as absolute anyway.
bool has_scheme(std::string_view uri) {
  const auto colon = uri.find(':');
  if (colon == std::string_view::npos || colon < 2) return false;
  for (std::size_t i = 0; i < colon; ++i) {
    const char c = uri[i];
    const bool alpha = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!alpha && (i == 0 || !((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'))) return false;
  }
  return true;
}

double srgb_encoded(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// The node's own transform: its matrix, or translation * rotation * scale.
glm::dmat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) m = glm::translate(m, glm::make_vec3(node.translation.data()));
  if (node.rotation.size() == 4) {
    const auto& r = node.rotation;
    m *= glm::mat4_cast(glm::normalize(glm::dquat(r[3], r[0], r[1], r[2])));
  }
  if (node.scale.size() == 3) m = glm::scale(m, glm::make_vec3(node.scale.data()));
  return m;
}

// A UV transform of KHR_texture_transform (offset * rotation * scale), in
// glTF's texture space (v down).
struct UvTransform {
  glm::dvec2 offset{0.0};
  double rotation = 0.0;
  glm::dvec2 scale{1.0};

  glm::dvec2 apply(glm::dvec2 uv) const {
    uv *= scale;
    const double c = std::cos(rotation);
    const double s = std::sin(rotation);
    return offset + glm::dvec2(c * uv.x + s * uv.y, -s * uv.x + c * uv.y);
  }
};

// The base colour texture's texcoord set and UV transform of a material.
struct TexcoordChoice {
  int set = 0;
  std::optional<UvTransform> transform;
};

struct MeshInstance {
  int mesh = 0;
  glm::dmat4 transform{1.0};
  int node = -1;  // the node that draws it; -1 in a file without nodes
};

// Exact-bits hash of a position and its colour, so coinciding vertices of
// different primitives become one position as in an OBJ.
struct WeldKey {
  std::array<std::uint64_t, 7> bits;
  bool operator==(const WeldKey&) const = default;
};
struct WeldKeyHash {
  std::size_t operator()(const WeldKey& k) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint64_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// The mesh source as the primitives add to it.
struct SourceInProgress {
  MeshSource source;
  std::unordered_map<WeldKey, std::uint32_t, WeldKeyHash> welded;
  std::vector<glm::dvec3> colours;  // per welded position, sRGB-encoded
  bool any_colour = false;
  bool colour_alpha = false;
};

// Where a primitive's normals, texture coordinates and tangents begin in
// the source's lists; -1 where it has none.
struct CornerBases {
  std::int64_t normal = -1;
  std::int64_t texcoord = -1;
  std::int64_t tangent = -1;
};

int attribute_of(const tinygltf::Primitive& primitive, const std::string& key) {
  const auto it = primitive.attributes.find(key);
  return it == primitive.attributes.end() ? -1 : it->second;
}

// A primitive's triangles, as its mode strings its corners together; a
// mirroring node turns each one over so that it still faces out.
void add_triangles(MeshSource& source, const tinygltf::Primitive& primitive, const std::vector<std::uint32_t>& corners,
                   const std::vector<std::uint32_t>& position_of, const CornerBases& bases, bool mirrored) {
  const auto from = [](std::int64_t base, std::uint32_t pick) { return base < 0 ? -1 : base + pick; };
  const auto add_triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    SourceTriangle tri;
    const std::uint32_t picks[3] = {a, mirrored ? c : b, mirrored ? b : c};
    for (int k = 0; k < 3; ++k) {
      SourceCorner& corner = tri.corner[k];
      corner.position = position_of[picks[k]];
      corner.normal = from(bases.normal, picks[k]);
      corner.texcoord = from(bases.texcoord, picks[k]);
      corner.tangent = from(bases.tangent, picks[k]);
    }
    tri.material = primitive.material;
    source.triangles.push_back(tri);
  };
  const std::size_t n = corners.size();
  if (primitive.mode == TINYGLTF_MODE_TRIANGLES) {
    for (std::size_t i = 0; i + 2 < n; i += 3) add_triangle(corners[i], corners[i + 1], corners[i + 2]);
  } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < n; ++i) {
      if (i % 2 == 0) {
        add_triangle(corners[i], corners[i + 1], corners[i + 2]);
      } else {
        add_triangle(corners[i + 1], corners[i], corners[i + 2]);
      }
    }
  } else {
    for (std::size_t i = 1; i + 1 < n; ++i) add_triangle(corners[0], corners[i], corners[i + 1]);
  }
}

// The bytes tinygltf may read, by the names the importer gave them: the
// file-system callbacks serve these and nothing else, so no URI in a file
// can reach the disk or the network.
struct BufferSources {
  std::map<std::string, std::string_view> views;
  std::map<std::string, std::vector<std::uint8_t>> owned;
};

bool source_exists(const std::string& name, void* user) {
  const auto* sources = static_cast<const BufferSources*>(user);
  return sources->views.contains(name) || sources->owned.contains(name);
}

std::string source_name_as_is(const std::string& name, void*) { return name; }

bool read_source(std::vector<unsigned char>* out, std::string* err, const std::string& name, void* user) {
  auto* sources = static_cast<BufferSources*>(user);
  if (const auto it = sources->owned.find(name); it != sources->owned.end()) {
    *out = std::move(it->second);
    sources->owned.erase(it);
    return true;
  }
  if (const auto it = sources->views.find(name); it != sources->views.end()) {
    out->assign(it->second.begin(), it->second.end());
    return true;
  }
  if (err) *err += "not part of the upload";
  return false;
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not allowed";
  return false;
}

// Images are read by the importer itself (tinygltf is given none), so this
// is never consulted; it keeps tinygltf's own decoder out in any case.
bool keep_image_undecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                          void*) {
  return true;
}

class GltfImporter {
 public:
  GltfImporter(const Bundle& bundle, std::string path, const ImportLimits& limits, const ImportChoices& choices,
               GltfOrigin origin)
      : bundle_(bundle),
        path_(std::move(path)),
        limits_(limits),
        scene_(choices.gltf_scene),
        choices_(choices),
        origin_(origin) {}

  Model run() {
    const GltfContainer container = open_gltf_container(*bundle_.find(path_), path_);
    parse_json(container.json);
    check_required_extensions();
    warn_unread_extensions();
    draco_primitives_ = take_draco_primitives(doc_, path_);
    BufferSources sources = prepare_buffers(container.bin);
    // Images are decoded only for the materials that use them, by the
    // importer's own decoders with their limits.
    images_ = doc_.contains("images") ? std::move(doc_["images"]) : json::array();
    doc_.erase("images");
    load(sources);
    restore_draco_indices(draco_primitives_, gltf_);
    check_import_time(limits_, "parsing " + path_);
    meshopt_views_ = std::make_unique<MeshoptViews>(doc_, gltf_, meshopt_fallbacks_, path_, limits_);
    reader_ = std::make_unique<GltfAccessorReader>(gltf_, path_, [this](int view) { return decoded_view(view); });

    const std::vector<MeshInstance> instances = collect_instances();
    check_counts(instances);
    decode_draco(instances);
    rig_reader_ =
        std::make_unique<GltfRigReader>(gltf_, *reader_, path_, drawn_nodes_, up_axis_turn(choices_.z_up()), warnings_);
    MeshSource source = make_source(instances);
    source.limits = limits_;
    apply_import_choices(source, choices_);
    // glTF 2.0 §3.7.2.1: without NORMAL, flat normals. A converted file's
    // missing normals were missing in the original, which said nothing.
    if (origin_ == GltfOrigin::File) source.smooth_angle_deg = kFlatSmoothAngle;
    model_.mesh = build_mesh(source, warnings_, [this](std::vector<SourceTriangle>& triangles) {
      build_materials(triangles);
      check_import_time(limits_, "decoding textures");
    });
    if (rig_reader_->moves()) {
      const glm::dmat4 file_to_mesh =
          glm::translate(glm::dmat4(1.0), -model_.mesh.origin) * glm::dmat4(up_axis_turn(choices_.z_up()));
      model_.rig = std::make_shared<const Rig>(rig_reader_->finish(file_to_mesh));
      check_import_time(limits_, "reading clips");
    }
    report_ignored();
    model_.has_vertex_colors = !model_.mesh.colors.empty();
    model_.warnings = warnings_.take();
    return std::move(model_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw ImportError(path_, path_ + ": " + message); }

  // The bytes of a buffer view that a compression extension holds.
  std::optional<std::span<const std::uint8_t>> decoded_view(int view) {
    if (const auto it = draco_views_.find(view); it != draco_views_.end()) return it->second;
    return meshopt_views_->bytes(view);
  }

  // The Draco primitives of the drawn meshes, each decoded once however
  // often its mesh is placed. Runs after check_counts, so the counts the
  // decoded meshes must match are within the limits.
  void decode_draco(const std::vector<MeshInstance>& instances) {
    std::set<int> drawn;
    for (const MeshInstance& instance : instances) drawn.insert(instance.mesh);
    for (const DracoPrimitive& primitive : draco_primitives_) {
      if (drawn.contains(primitive.mesh)) {
        decode_draco_primitive(primitive, gltf_, *reader_, draco_views_, limits_, path_);
      }
    }
    if (!draco_primitives_.empty()) check_import_time(limits_, "decoding Draco meshes");
  }

  void parse_json(std::string_view text) {
    try {
      doc_ = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
      fail(std::string("not valid glTF JSON (") + e.what() + ")");
    }
    const json& version = member(member(doc_, "asset"), "version");
    if (!version.is_string()) fail("not a glTF document (it has no asset.version)");
    const auto v = version.get<std::string>();
    if (!v.starts_with("2.")) fail("glTF version " + in_quotes(v) + " is not read (only 2.x)");
  }

  void check_required_extensions() const {
    const json& required = member(doc_, "extensionsRequired");
    if (!required.is_array()) return;
    for (const json& name : required) {
      if (!name.is_string()) continue;
      const auto text = name.get<std::string>();
      if (!reads_extension(text)) {
        std::string known;
        for (const std::string_view read : kReadExtensions) known += (known.empty() ? "" : ", ") + std::string(read);
        fail("the file requires the glTF extension " + in_quotes(text) + ", which toond does not read (it reads " +
             known + ")");
      }
    }
  }

  void warn_unread_extensions() {
    // A converted file's extensions are the converter's choice; what the
    // original held and the model lacks the converter says itself.
    if (origin_ == GltfOrigin::Converted) return;
    const json& used = member(doc_, "extensionsUsed");
    if (!used.is_array()) return;
    std::string names;
    for (const json& name : used) {
      if (name.is_string() && !reads_extension(name.get<std::string>())) {
        names += (names.empty() ? "" : ", ") + name.get<std::string>();
      }
    }
    if (!names.empty()) warnings_.add(path_ + ": glTF extensions not read, drawn without them: " + names);
  }

  // The bundle path a URI of the file names. A URI that would leave the
  // bundle is refused outright; one that names no file of the bundle gives
  // nullopt.
  std::optional<std::string> resolve_uri(const std::string& uri, const std::string& role) const {
    const auto refuse = [&](const std::string& why) {
      fail(role + " has the URI " + in_quotes(uri.substr(0, 200)) + ", " + why +
           "; a glTF upload may only name files of the upload or carry data: URIs");
    };
    if (has_scheme(uri)) refuse("which points outside the upload");
    const std::string decoded = bundle_paths::uri_reference(uri);
    if (decoded.empty()) refuse("which is empty");
    const bundle_paths::Refusal refusal = bundle_paths::resolve_reference(path_, decoded).refusal;
    if (refusal == bundle_paths::Refusal::absolute) refuse("an absolute path");
    if (refusal != bundle_paths::Refusal::none) refuse("which leaves the upload's folder");
    return bundle_.resolve(path_, decoded);
  }

  // The bundle file a converted file's image names: the path as the
  // original file wrote it, relative to the file, or else its file name
  // alone anywhere beside the file (with a warning).
  std::optional<std::string> find_converted_image(const std::string& written, const std::string& role) {
    const auto found = find_image(bundle_, path_, written);
    if (!found) return std::nullopt;
    if (found->match != ImageMatch::Path) {
      warnings_.add(path_ + ": " + role + " " + in_quotes(written) + " " + describe_match(*found));
    }
    return found->path;
  }

  bool uses_extension(std::string_view name) const {
    for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
      const json& names = member(doc_, list);
      if (names.is_array() && std::find(names.begin(), names.end(), json(std::string(name))) != names.end())
        return true;
    }
    return false;
  }

  // Gives every buffer a name the file-system callbacks serve: the GLB's
  // BIN chunk, a decoded data: URI, or a bundle file, cut to the buffer's
  // declared length. A buffer that only stands in for EXT_meshopt_compression
  // views is not loaded: those views are decoded from their compressed
  // bytes, even where the stand-in has a file of its own.
  BufferSources prepare_buffers(const std::optional<std::string_view>& bin) {
    BufferSources sources;
    json& buffers = doc_["buffers"];
    if (buffers.is_null()) buffers = json::array();
    if (!buffers.is_array()) fail("'buffers' is not a list");
    const bool uses_meshopt = uses_extension("EXT_meshopt_compression");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      json& buffer = buffers[i];
      const std::string role = "buffer " + std::to_string(i);
      const json& length_value = member(buffer, "byteLength");
      if (!length_value.is_number_unsigned() && !length_value.is_number_integer()) fail(role + " has no byteLength");
      const auto length = length_value.get<std::uint64_t>();
      const std::string name = "toond-buffer-" + std::to_string(i);
      const json& uri_value = member(buffer, "uri");
      const bool has_data = uri_value.is_string() || (i == 0 && bin);
      if (is_meshopt_fallback(buffer, has_data, uses_meshopt)) {
        // tinygltf refuses a buffer without bytes; one zero byte stands in,
        // and MeshoptViews refuses any view that would read it.
        static constexpr char kStandIn[1] = {0};
        sources.views[name] = std::string_view(kStandIn, 1);
        buffer["byteLength"] = 1;
        buffer["uri"] = name;
        meshopt_fallbacks_.insert(static_cast<int>(i));
        continue;
      }
      std::string_view bytes;
      if (uri_value.is_string() && is_data_uri(uri_value.get<std::string>())) {
        auto decoded = decode_data_uri(uri_value.get<std::string>());
        if (!decoded) fail(role + " has a data: URI that is not base64");
        if (decoded->bytes.size() < length) {
          fail(role + " declares " + std::to_string(length) + " bytes but its data: URI holds " +
               std::to_string(decoded->bytes.size()));
        }
        decoded->bytes.resize(static_cast<std::size_t>(length));
        sources.owned[name] = std::move(decoded->bytes);
      } else {
        std::string from;
        if (uri_value.is_string()) {
          const auto path = resolve_uri(uri_value.get<std::string>(), role);
          if (!path) fail(role + " names " + in_quotes(uri_value.get<std::string>()) + ", which is not in the upload");
          bytes = *bundle_.find(*path);
          from = in_quotes(*path);
        } else if (i == 0 && bin) {
          bytes = *bin;
          from = "the GLB's binary chunk";
        } else {
          fail(role + " has no URI (only the first buffer of a .glb may use the binary chunk)");
        }
        if (bytes.size() < length) {
          fail(role + " declares " + std::to_string(length) + " bytes but " + from + " holds " +
               std::to_string(bytes.size()));
        }
        sources.views[name] = bytes.substr(0, static_cast<std::size_t>(length));
      }
      buffer["uri"] = name;
    }
    return sources;
  }

  void load(BufferSources& sources) {
    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = &source_exists;
    callbacks.ExpandFilePath = &source_name_as_is;
    callbacks.ReadWholeFile = &read_source;
    callbacks.WriteWholeFile = &refuse_write;
    callbacks.user_data = &sources;
    loader.SetFsCallbacks(callbacks);
    loader.SetImageLoader(&keep_image_undecoded, nullptr);
    const std::string text = doc_.dump();
    std::string err;
    std::string warn;
    bool ok = false;
    try {
      ok = loader.LoadASCIIFromString(&gltf_, &err, &warn, text.data(), static_cast<unsigned int>(text.size()), "");
    } catch (const std::exception& e) {
      err = e.what();
    }
    if (!ok) {
      std::string reason = err.substr(0, err.find('\n'));
      if (reason.empty()) reason = "the parser gave no reason";
      fail("cannot read the glTF document: " + reason);
    }
  }

  std::vector<MeshInstance> collect_instances() {
    std::vector<MeshInstance> instances;
    std::vector<int> roots;
    const auto& scenes = gltf_.scenes;
    if (!scenes.empty()) {
      int chosen = scene_.value_or(gltf_.defaultScene >= 0 ? gltf_.defaultScene : 0);
      if (chosen < 0 || static_cast<std::size_t>(chosen) >= scenes.size()) {
        if (scene_) {
          fail("scene " + std::to_string(chosen) + " was asked for, but the file has " + std::to_string(scenes.size()) +
               " scenes");
        }
        warnings_.add(path_ + ": the default scene " + std::to_string(chosen) + " does not exist; scene 0 is drawn");
        chosen = 0;
      }
      roots = scenes[static_cast<std::size_t>(chosen)].nodes;
      if (scenes.size() > 1) {
        warnings_.add(path_ + ": the file has " + std::to_string(scenes.size()) + " scenes; scene " +
                      std::to_string(chosen) + " is drawn (an upload with ?scene=N picks another)");
      }
    } else if (scene_) {
      fail("scene " + std::to_string(*scene_) + " was asked for, but the file has no scenes");
    } else if (!gltf_.nodes.empty()) {
      // No scene: every node that is nobody's child is a root.
      std::vector<bool> is_child(gltf_.nodes.size(), false);
      for (const auto& node : gltf_.nodes) {
        for (const int child : node.children) {
          if (child >= 0 && static_cast<std::size_t>(child) < is_child.size())
            is_child[static_cast<std::size_t>(child)] = true;
        }
      }
      for (std::size_t i = 0; i < is_child.size(); ++i) {
        if (!is_child[i]) roots.push_back(static_cast<int>(i));
      }
    } else {
      for (std::size_t m = 0; m < gltf_.meshes.size(); ++m) instances.push_back({static_cast<int>(m), glm::dmat4(1.0)});
      return instances;
    }

    // A node hierarchy is a tree; a node reached twice (a cycle, or two
    // parents) is drawn once, so a hostile file cannot loop or multiply.
    std::vector<bool> visited(gltf_.nodes.size(), false);
    drawn_nodes_.assign(gltf_.nodes.size(), false);
    std::vector<std::pair<int, glm::dmat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::dmat4(1.0));
    bool reached_twice = false;
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || static_cast<std::size_t>(index) >= gltf_.nodes.size())
        fail("a scene refers to node " + std::to_string(index) + ", which does not exist");
      if (visited[static_cast<std::size_t>(index)]) {
        reached_twice = true;
        continue;
      }
      visited[static_cast<std::size_t>(index)] = true;
      drawn_nodes_[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = gltf_.nodes[static_cast<std::size_t>(index)];
      const glm::dmat4 world = parent * local_transform(node);
      if (node.mesh >= 0) {
        if (static_cast<std::size_t>(node.mesh) >= gltf_.meshes.size()) {
          fail("node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) +
               ", which does not exist");
        }
        instances.push_back({node.mesh, world, index});
      }
      if (node.camera >= 0) ++ignored_["cameras"];
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.emplace_back(*it, world);
    }
    if (reached_twice) warnings_.add(path_ + ": a node is reached twice in the node hierarchy; it is drawn once");
    return instances;
  }

  static std::uint64_t triangles_of(int mode, std::uint64_t corners) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return corners / 3;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN)
      return corners < 3 ? 0 : corners - 2;
    return 0;
  }

  static bool is_triangles(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
  }

  std::string primitive_name(int mesh, std::size_t primitive) const {
    return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
  }

  // What the drawn primitives would make, from the accessors' counts alone,
  // before anything is read or allocated.
  void check_counts(const std::vector<MeshInstance>& instances) const {
    std::uint64_t vertices = 0;
    std::uint64_t triangles = 0;
    for (const MeshInstance& instance : instances) {
      const auto& primitives = gltf_.meshes[static_cast<std::size_t>(instance.mesh)].primitives;
      for (std::size_t p = 0; p < primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = primitives[p];
        if (!is_triangles(primitive.mode)) continue;
        const std::string name = primitive_name(instance.mesh, p);
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) fail(name + " has no POSITION attribute and cannot be drawn");
        const std::uint64_t count = reader_->accessor(position->second, name + " POSITION").count;
        const std::uint64_t corners =
            primitive.indices >= 0 ? reader_->accessor(primitive.indices, name + " indices").count : count;
        vertices += count;
        triangles += triangles_of(primitive.mode, corners);
      }
    }
    if (vertices > limits_.max_vertices) {
      throw ImportLimitError(
          path_, ImportLimit::Vertices, static_cast<double>(limits_.max_vertices),
          path_ + " has " + std::to_string(vertices) + " vertices in its drawn primitives, more than");
    }
    if (triangles > limits_.max_triangles) {
      throw ImportLimitError(
          path_, ImportLimit::Triangles, static_cast<double>(limits_.max_triangles),
          path_ + " has " + std::to_string(triangles) + " triangles in its drawn primitives, more than");
    }
  }

  const json& material_json(int material) const {
    return element(member(doc_, "materials"), static_cast<std::size_t>(std::max(material, 0)));
  }

  // Which TEXCOORD set, with which transform, the base colour texture of
  // `material` samples.
  TexcoordChoice texcoord_choice(int material) {
    TexcoordChoice choice;
    if (material < 0) return choice;
    const json& info = member(member(material_json(material), "pbrMetallicRoughness"), "baseColorTexture");
    choice.set = index_or(member(info, "texCoord"), 0);
    const json& transform = member(member(info, "extensions"), "KHR_texture_transform");
    if (transform.is_object()) {
      UvTransform t;
      const json& offset = member(transform, "offset");
      const json& scale = member(transform, "scale");
      t.offset = {number_or(element(offset, 0), 0.0), number_or(element(offset, 1), 0.0)};
      t.scale = {number_or(element(scale, 0), 1.0), number_or(element(scale, 1), 1.0)};
      t.rotation = number_or(member(transform, "rotation"), 0.0);
      choice.set = index_or(member(transform, "texCoord"), choice.set);
      choice.transform = t;
    }
    const json& normal = member(material_json(material), "normalTexture");
    if (normal.is_object() && index_or(member(normal, "texCoord"), 0) != choice.set) {
      warnings_.add(path_ + ": material " + std::to_string(material) +
                    " samples its normal map with other texture coordinates than its colour; both use TEXCOORD_" +
                    std::to_string(choice.set));
    }
    return choice;
  }

  // The drawn primitives in the shared importer's terms: each instance's
  // primitives placed by its node's matrix, positions welded across them.
  MeshSource make_source(const std::vector<MeshInstance>& instances) {
    SourceInProgress building;
    building.source.file = path_;
    std::size_t skipped_modes = 0;
    for (const MeshInstance& instance : instances) {
      const tinygltf::Mesh& mesh = gltf_.meshes[static_cast<std::size_t>(instance.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        if (is_triangles(mesh.primitives[p].mode)) {
          add_primitive(building, instance, mesh.primitives[p], primitive_name(instance.mesh, p));
        } else {
          ++skipped_modes;
        }
      }
    }
    if (skipped_modes > 0) {
      warnings_.add(path_ + ": " + std::to_string(skipped_modes) +
                    " point or line primitives are not drawn (only triangles are)");
    }
    if (building.colour_alpha) warnings_.add(path_ + ": vertex colour alpha is not drawn; the colours are opaque");
    if (building.any_colour) building.source.colors = std::move(building.colours);
    return std::move(building.source);
  }

  // One primitive's vertices and triangles, read in the order that decides
  // which of its faults is told first.
  void add_primitive(SourceInProgress& building, const MeshInstance& instance, const tinygltf::Primitive& primitive,
                     const std::string& name) {
    const glm::dmat3 linear(instance.transform);
    const std::vector<double> positions = reader_->read(attribute_of(primitive, "POSITION"), name + " POSITION", 3);
    const std::size_t count = positions.size() / 3;
    const std::vector<std::uint32_t> position_of = weld_positions(building, instance, primitive, positions, name);
    MeshSource& source = building.source;
    CornerBases bases;
    if (attribute_of(primitive, "NORMAL") >= 0) bases.normal = add_normals(source, primitive, linear, count, name);
    if (attribute_of(primitive, "TANGENT") >= 0) bases.tangent = add_tangents(source, primitive, linear, count, name);
    const TexcoordChoice uv = texcoord_choice(primitive.material);
    if (attribute_of(primitive, "TEXCOORD_" + std::to_string(uv.set)) >= 0) {
      bases.texcoord = add_texcoords(source, primitive, uv, count, name);
    }
    const bool mirrored = glm::determinant(linear) < 0.0;
    add_triangles(source, primitive, corners_of(primitive, count, name), position_of, bases, mirrored);
  }

  void check_count(const std::vector<double>& values, int width, std::size_t count, const std::string& what,
                   const std::string& name) const {
    if (values.size() != count * static_cast<std::size_t>(width)) {
      fail(name + " has " + std::to_string(values.size() / static_cast<std::size_t>(width)) + " " + what + " for " +
           std::to_string(count) + " positions");
    }
  }

  // How each vertex of a primitive moves, when anything in the file does.
  std::vector<std::uint32_t> motions_of(const MeshInstance& instance, const tinygltf::Primitive& primitive,
                                        std::size_t count, const std::string& name) {
    if (!rig_reader_->moves()) return {};
    if (instance.node < 0) fail(name + " is drawn without a node in a file whose nodes move");
    return rig_reader_->motions_of(instance.node, primitive, count, name);
  }

  // The primitive's positions placed, each merged with an equal one (same
  // colour, same motion) seen before: the welded position of each vertex.
  std::vector<std::uint32_t> weld_positions(SourceInProgress& building, const MeshInstance& instance,
                                            const tinygltf::Primitive& primitive, const std::vector<double>& positions,
                                            const std::string& name) {
    const std::size_t count = positions.size() / 3;
    std::vector<double> colours_in;
    if (attribute_of(primitive, "COLOR_0") >= 0) {
      colours_in = reader_->read(attribute_of(primitive, "COLOR_0"), name + " COLOR_0", 4, {3});
      check_count(colours_in, 4, count, "colours", name);
      building.any_colour = true;
    }
    const std::vector<std::uint32_t> motions = motions_of(instance, primitive, count, name);
    std::vector<std::uint32_t> position_of(count);
    for (std::size_t i = 0; i < count; ++i) {
      const glm::dvec3 p3 = glm::dvec3(instance.transform *
                                       glm::dvec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0));
      glm::dvec3 colour(1.0);
      if (!colours_in.empty()) {
        colour = {srgb_encoded(colours_in[4 * i]), srgb_encoded(colours_in[4 * i + 1]),
                  srgb_encoded(colours_in[4 * i + 2])};
        building.colour_alpha = building.colour_alpha || colours_in[4 * i + 3] < 1.0;
      }
      const WeldKey key{{std::bit_cast<std::uint64_t>(p3.x), std::bit_cast<std::uint64_t>(p3.y),
                         std::bit_cast<std::uint64_t>(p3.z), std::bit_cast<std::uint64_t>(colour.r),
                         std::bit_cast<std::uint64_t>(colour.g), std::bit_cast<std::uint64_t>(colour.b),
                         motions.empty() ? 0u : motions[i]}};
      const auto [it, added] =
          building.welded.try_emplace(key, static_cast<std::uint32_t>(building.source.positions.size()));
      if (added) {
        building.source.positions.push_back(p3);
        building.colours.push_back(colour);
        if (!motions.empty()) building.source.motions.push_back(motions[i]);
      }
      position_of[i] = it->second;
    }
    return position_of;
  }

  // The primitive's normals, turned by the node's normal matrix; returns
  // the index of the first.
  std::int64_t add_normals(MeshSource& source, const tinygltf::Primitive& primitive, const glm::dmat3& linear,
                           std::size_t count, const std::string& name) {
    const std::int64_t base = static_cast<std::int64_t>(source.normals.size());
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    const std::vector<double> normals = reader_->read(attribute_of(primitive, "NORMAL"), name + " NORMAL", 3);
    check_count(normals, 3, count, "normals", name);
    for (std::size_t i = 0; i < count; ++i) {
      source.normals.push_back(normal_matrix * glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]));
    }
    return base;
  }

  // A tangent lies in the surface: it turns with the node's matrix itself,
  // and a mirroring matrix turns the bitangent's hand.
  std::int64_t add_tangents(MeshSource& source, const tinygltf::Primitive& primitive, const glm::dmat3& linear,
                            std::size_t count, const std::string& name) {
    const std::int64_t base = static_cast<std::int64_t>(source.tangents.size());
    const std::vector<double> tangents = reader_->read(attribute_of(primitive, "TANGENT"), name + " TANGENT", 4);
    check_count(tangents, 4, count, "tangents", name);
    const double hand = glm::determinant(linear) < 0.0 ? -1.0 : 1.0;
    for (std::size_t i = 0; i < count; ++i) {
      const glm::dvec3 along = linear * glm::dvec3(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
      source.tangents.emplace_back(along, tangents[4 * i + 3] * hand);
    }
    return base;
  }

  // The texture coordinates the material's colour texture samples, with
  // its transform applied.
  std::int64_t add_texcoords(MeshSource& source, const tinygltf::Primitive& primitive, const TexcoordChoice& uv,
                             std::size_t count, const std::string& name) {
    const std::int64_t base = static_cast<std::int64_t>(source.texcoords.size());
    const std::string set = "TEXCOORD_" + std::to_string(uv.set);
    const std::vector<double> texcoords = reader_->read(attribute_of(primitive, set), name + " " + set, 2);
    check_count(texcoords, 2, count, "texture coordinates", name);
    for (std::size_t i = 0; i < count; ++i) {
      glm::dvec2 t(texcoords[2 * i], texcoords[2 * i + 1]);
      if (uv.transform) t = uv.transform->apply(t);
      // glTF's v runs down the image, the mesh's up (as in OBJ).
      source.texcoords.emplace_back(t.x, 1.0 - t.y);
    }
    return base;
  }

  // The primitive's corners: its indices, checked, or its vertices in order.
  std::vector<std::uint32_t> corners_of(const tinygltf::Primitive& primitive, std::size_t count,
                                        const std::string& name) {
    std::vector<std::uint32_t> corners;
    if (primitive.indices < 0) {
      corners.resize(count);
      for (std::size_t i = 0; i < count; ++i) corners[i] = static_cast<std::uint32_t>(i);
      return corners;
    }
    corners = reader_->read_indices(primitive.indices, name + " indices");
    for (const std::uint32_t c : corners) {
      if (c >= count)
        fail(name + " has the index " + std::to_string(c) + ", past its " + std::to_string(count) + " vertices");
    }
    return corners;
  }

  // The bytes of image `index` and a name for messages, or nullopt with a
  // warning.
  std::optional<std::pair<std::string, std::string>> image_bytes(int index, const std::string& role) {
    const json& image = element(images_, static_cast<std::size_t>(std::max(index, 0)));
    if (index < 0 || !image.is_object()) {
      warnings_.add(path_ + ": " + role + " refers to image " + std::to_string(index) + ", which does not exist");
      return std::nullopt;
    }
    const std::string name = path_ + " image " + std::to_string(index);
    const json& uri = member(image, "uri");
    if (uri.is_string()) {
      const auto text = uri.get<std::string>();
      if (is_data_uri(text)) {
        auto decoded = decode_data_uri(text);
        if (!decoded) {
          warnings_.add(name + ": its data: URI is not base64; " + role + " is left out");
          return std::nullopt;
        }
        return std::make_pair(name, std::string(decoded->bytes.begin(), decoded->bytes.end()));
      }
      const auto path = origin_ == GltfOrigin::Converted ? find_converted_image(text, role)
                                                         : resolve_uri(text, "image " + std::to_string(index));
      if (!path) {
        warnings_.add(name + ": " + in_quotes(text) + " is not in the upload; " + role + " is left out");
        return std::nullopt;
      }
      return std::make_pair(*path, *bundle_.find(*path));
    }
    const int view = index_or(member(image, "bufferView"), -1);
    if (view < 0) {
      warnings_.add(name + " has neither a URI nor a buffer view; " + role + " is left out");
      return std::nullopt;
    }
    const auto bytes = reader_->view(view, name);
    return std::make_pair(name, std::string(bytes.begin(), bytes.end()));
  }

  // The model texture of glTF texture `index` in `space`, or -1 with a
  // warning when it cannot be used.
  int texture_for(int index, ColorSpace space, const std::string& role) {
    const json& texture = element(member(doc_, "textures"), static_cast<std::size_t>(std::max(index, 0)));
    if (index < 0 || !texture.is_object()) {
      warnings_.add(path_ + ": " + role + " refers to texture " + std::to_string(index) + ", which does not exist");
      return -1;
    }
    const json& extensions = member(texture, "extensions");
    std::vector<int> candidates;
    if (const int webp = index_or(member(member(extensions, "EXT_texture_webp"), "source"), -1); webp >= 0) {
      candidates.push_back(webp);
    }
    if (const int plain = index_or(member(texture, "source"), -1); plain >= 0) candidates.push_back(plain);
    if (candidates.empty()) {
      const bool ktx = member(extensions, "KHR_texture_basisu").is_object();
      warnings_.add(path_ + ": " + role +
                    (ktx ? " exists only as a KTX2/Basis image, which toond cannot decode" : " has no image") +
                    "; the material is drawn without it");
      return -1;
    }
    for (const int image : candidates) {
      const auto key = std::make_pair(image, space);
      if (const auto it = texture_slots_.find(key); it != texture_slots_.end()) return it->second;
      const auto bytes = image_bytes(image, role);
      if (!bytes) continue;
      try {
        Texture decoded =
            decode_model_texture(bytes->second, bytes->first, limits_.max_texture_pixels, texture_pixels_left_);
        decoded.color_space = space;
        model_.textures.push_back(std::move(decoded));
        const int slot = static_cast<int>(model_.textures.size()) - 1;
        texture_slots_.emplace(key, slot);
        return slot;
      } catch (const ImportLimitError&) {
        throw;
      } catch (const std::exception& e) {
        warnings_.add(bytes->first + ": " + role + " cannot be used: " + e.what());
      }
    }
    warnings_.add(path_ + ": " + role + " is left out; the material is drawn without it");
    return -1;
  }

  Material make_material(int id) {
    const json& m = material_json(id);
    const std::string label = "material " + std::to_string(id);
    Material material;
    material.name = member(m, "name").is_string() ? member(m, "name").get<std::string>() : label;
    const json& pbr = member(m, "pbrMetallicRoughness");
    const json& factor = member(pbr, "baseColorFactor");
    glm::dvec3 base(1.0);
    for (int c = 0; c < 3; ++c)
      base[c] = std::clamp(number_or(element(factor, static_cast<std::size_t>(c)), 1.0), 0.0, 1.0);
    material.opacity = static_cast<float>(std::clamp(number_or(element(factor, 3), 1.0), 0.0, 1.0));
    const json& emissive = member(m, "emissiveFactor");
    for (int c = 0; c < 3; ++c)
      base[c] = std::min(1.0, base[c] + std::max(0.0, number_or(element(emissive, static_cast<std::size_t>(c)), 0.0)));
    material.diffuse = glm::vec3(base);
    if (const json& info = member(pbr, "baseColorTexture"); info.is_object()) {
      material.diffuse_texture =
          texture_for(index_or(member(info, "index"), -1), ColorSpace::Srgb, label + "'s base colour texture");
    }
    if (const json& info = member(m, "normalTexture"); info.is_object()) {
      material.normal_texture =
          texture_for(index_or(member(info, "index"), -1), ColorSpace::Linear, label + "'s normal map");
      if (number_or(member(info, "scale"), 1.0) != 1.0) ++ignored_["normal map scales"];
    }
    // Roughness decides only whether the material is matte (is_matte); a
    // metal is drawn as its base colour.
    if (member(pbr, "metallicRoughnessTexture").is_object() || number_or(member(pbr, "metallicFactor"), 0.0) > 0.0) {
      ++ignored_["metallic-roughness (materials)"];
    }
    if (member(m, "occlusionTexture").is_object()) ++ignored_["occlusion textures"];
    if (member(m, "emissiveTexture").is_object()) ++ignored_["emissive textures (the emissive factor is added)"];
    const json& mode = member(m, "alphaMode");
    const std::string alpha_mode = mode.is_string() ? mode.get<std::string>() : "OPAQUE";
    material.alpha_cutoff = static_cast<float>(std::clamp(number_or(member(m, "alphaCutoff"), 0.5), 0.0, 1.0));
    if (alpha_mode == "MASK") material.alpha_mode = AlphaMode::Mask;
    if (alpha_mode == "BLEND") material.alpha_mode = AlphaMode::Blend;
    material.unlit = member(member(m, "extensions"), "KHR_materials_unlit").is_object();
    material.matte = is_matte(m);
    if (const json& info = member(pbr, "baseColorTexture"); info.is_object()) {
      material.sampler = sampler_of(index_or(member(info, "index"), -1));
    }
    return material;
  }

  // Whether the material says it has no highlight: a specular extension's
  // zero specular (assimp writes KHR_materials_pbrSpecularGlossiness for the
  // files it converts), or, without one, a surface fully rough everywhere
  // (roughnessFactor 1, glTF's default, and no texture to vary it).
  static bool is_matte(const json& m) {
    const json& extensions = member(m, "extensions");
    const auto all_zero = [](const json& factor, double absent) {
      if (!factor.is_array()) return absent == 0.0;
      for (const json& c : factor) {
        if (!c.is_number() || c.get<double>() != 0.0) return false;
      }
      return true;
    };
    if (const json& gloss = member(extensions, "KHR_materials_pbrSpecularGlossiness"); gloss.is_object()) {
      const bool no_texture = !member(gloss, "specularGlossinessTexture").is_object();
      return (all_zero(member(gloss, "specularFactor"), 1.0) && no_texture) ||
             (number_or(member(gloss, "glossinessFactor"), 1.0) <= 0.0 && no_texture);
    }
    if (const json& specular = member(extensions, "KHR_materials_specular"); specular.is_object()) {
      return number_or(member(specular, "specularFactor"), 1.0) <= 0.0 &&
             !member(specular, "specularTexture").is_object();
    }
    const json& pbr = member(m, "pbrMetallicRoughness");
    return number_or(member(pbr, "roughnessFactor"), 1.0) >= 1.0 &&
           !member(pbr, "metallicRoughnessTexture").is_object();
  }

  // glTF texture `index`'s sampler (glTF 2.0 §5.26), as far as toond draws
  // it; a missing or unknown value is left to the request.
  Sampler sampler_of(int index) const {
    Sampler sampler;
    const json& texture = element(member(doc_, "textures"), static_cast<std::size_t>(std::max(index, 0)));
    const int id = index_or(member(texture, "sampler"), -1);
    const json& s = element(member(doc_, "samplers"), static_cast<std::size_t>(std::max(id, 0)));
    if (index < 0 || id < 0 || !s.is_object()) return sampler;
    const auto filter = [](const json& value, bool minifying) {
      const int code = index_or(value, -1);
      if (code == 9728 || (minifying && (code == 9984 || code == 9986))) return TextureFilter::Nearest;
      if (code == 9729 || (minifying && (code == 9985 || code == 9987))) return TextureFilter::Linear;
      return TextureFilter::Unspecified;
    };
    const auto wrap = [](const json& value) {
      const int code = index_or(value, 10497);
      if (code == 33071) return TextureWrap::ClampToEdge;
      if (code == 33648) return TextureWrap::MirroredRepeat;
      return TextureWrap::Repeat;
    };
    sampler.magnification = filter(member(s, "magFilter"), false);
    sampler.minification = filter(member(s, "minFilter"), true);
    sampler.wrap_s = wrap(member(s, "wrapS"));
    sampler.wrap_t = wrap(member(s, "wrapT"));
    return sampler;
  }

  void build_materials(std::vector<SourceTriangle>& triangles) {
    const std::size_t material_count = gltf_.materials.size();
    std::set<int> used;
    for (auto& tri : triangles) {
      if (tri.material < 0 || static_cast<std::size_t>(tri.material) >= material_count) tri.material = -1;
      used.insert(tri.material);
    }
    std::map<int, int> slot;
    for (const int id : used) {
      slot[id] = static_cast<int>(model_.materials.size());
      if (id < 0) {
        Material fallback;
        fallback.name = "default";
        fallback.diffuse = glm::vec3(1.0f);
        model_.materials.push_back(std::move(fallback));
      } else {
        model_.materials.push_back(make_material(id));
      }
    }
    for (auto& tri : triangles) tri.material = slot.at(tri.material);
  }

  void report_ignored() {
    if (!gltf_.lights.empty()) ignored_["lights"] += gltf_.lights.size();
    std::string list;
    for (const auto& [what, count] : ignored_) list += (list.empty() ? "" : ", ") + std::to_string(count) + " " + what;
    if (!list.empty()) warnings_.add(path_ + ": not imported: " + list);
  }

  const Bundle& bundle_;
  std::string path_;
  ImportLimits limits_;
  std::optional<int> scene_;
  ImportChoices choices_;
  GltfOrigin origin_;
  json doc_;
  json images_;
  tinygltf::Model gltf_;
  std::vector<DracoPrimitive> draco_primitives_;
  std::map<int, std::vector<std::uint8_t>> draco_views_;
  std::set<int> meshopt_fallbacks_;
  std::unique_ptr<MeshoptViews> meshopt_views_;
  std::unique_ptr<GltfAccessorReader> reader_;
  std::unique_ptr<GltfRigReader> rig_reader_;
  std::vector<bool> drawn_nodes_;  // nodes of the drawn scene
  ImportWarnings warnings_;
  std::map<std::string, std::size_t> ignored_;
  std::map<std::pair<int, ColorSpace>, int> texture_slots_;
  std::uint64_t texture_pixels_left_ = kModelTexturePixels;
  Model model_;
};

}  // namespace

Model import_gltf_bundle(const Bundle& bundle, const std::string& path, const ImportLimits& limits,
                         const ImportChoices& choices, GltfOrigin origin) {
  return GltfImporter(bundle, path, limits, choices, origin).run();
}

}  // namespace toond::scene
