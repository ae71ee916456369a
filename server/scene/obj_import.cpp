#include "scene/obj_import.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "scene/import_error.h"
#include "scene/mesh_processing.h"
#include "scene/obj_text.h"
#include "scene/texture_decode.h"

namespace toond::scene {
namespace {

// A broken export can repeat one complaint per face; the answer must stay
// readable.
constexpr std::size_t kMaxWarnings = 40;

class Warnings {
 public:
  void add(std::string message) {
    if (!seen_.insert(message).second) return;
    if (list_.size() < kMaxWarnings) {
      list_.push_back(std::move(message));
    } else {
      ++dropped_;
    }
  }
  std::vector<std::string> take() {
    if (dropped_ > 0) list_.push_back(std::to_string(dropped_) + " further warnings left out");
    return std::move(list_);
  }

 private:
  std::vector<std::string> list_;
  std::unordered_set<std::string> seen_;
  std::size_t dropped_ = 0;
};

char ascii_lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

bool has_obj_extension(std::string_view path) {
  if (path.size() < 4) return false;
  std::string ext(path.substr(path.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(), ascii_lower);
  return ext == ".obj";
}

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

std::string find_obj(const Bundle& bundle) {
  std::vector<std::string> objs;
  for (const auto& [path, content] : bundle.files()) {
    if (has_obj_extension(path)) objs.push_back(path);
  }
  if (objs.size() == 1) return objs.front();
  if (objs.empty()) {
    std::string listing;
    for (const auto& [path, content] : bundle.files()) listing += (listing.empty() ? "" : ", ") + quoted(path);
    throw ImportError("", "the bundle holds no .obj file" + (listing.empty() ? std::string(" (it is empty)")
                                                                            : " (it holds " + listing + ")"));
  }
  std::string listing;
  for (const auto& path : objs) listing += (listing.empty() ? "" : ", ") + quoted(path);
  throw ImportError(objs[1], "the bundle holds " + std::to_string(objs.size()) + " .obj files (" + listing +
                                 "); a bundle is one model with exactly one .obj file");
}

// Names of the materials in an MTL text that have a Kd statement. Lines and
// names are cut exactly as tinyobj's LoadMtl cuts them (any of \n, \r\n, \r
// ends a line; the name is the rest of the newmtl line less trailing blanks),
// so the names match the ones it produced.
std::set<std::string> materials_with_kd(std::string_view mtl) {
  std::set<std::string> names;
  std::string current;
  std::size_t pos = 0;
  while (pos < mtl.size()) {
    const std::size_t end = std::min(mtl.find_first_of("\r\n", pos), mtl.size());
    std::string_view line = mtl.substr(pos, end - pos);
    pos = end + ((end + 1 < mtl.size() && mtl[end] == '\r' && mtl[end + 1] == '\n') ? 2 : 1);
    const auto last = line.find_last_not_of(" \t");
    line = last == std::string_view::npos ? std::string_view{} : line.substr(0, last + 1);
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos) continue;
    line.remove_prefix(first);
    const auto blank_at = [&](std::size_t i) { return i < line.size() && (line[i] == ' ' || line[i] == '\t'); };
    if (line.starts_with("newmtl") && blank_at(6)) {
      current = std::string(line.substr(7));
    } else if (line.starts_with("Kd") && blank_at(2)) {
      names.insert(current);
    }
  }
  return names;
}

// Serves `mtllib` names from the bundle instead of the file system, and
// remembers which MTL each material came from: texture names in an MTL are
// relative to the MTL's own folder.
class BundleMaterialReader : public tinyobj::MaterialReader {
 public:
  BundleMaterialReader(const Bundle& bundle, std::string obj_path, Warnings& warnings)
      : bundle_(bundle), obj_path_(std::move(obj_path)), warnings_(warnings) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* material_map, std::string*, std::string*) override {
    const std::string reference = trim(name);
    const auto path = bundle_.resolve(obj_path_, reference);
    if (!path) {
      warnings_.add(obj_path_ + ": material library " + quoted(reference) +
                    " is not in the bundle; its materials fall back to the default colour");
      return false;
    }
    std::istringstream in(*bundle_.find(*path));
    std::string warn;
    std::string err;
    tinyobj::LoadMtl(material_map, materials, &in, &warn, &err);
    for (const std::string* text : {&warn, &err}) {
      std::istringstream lines(*text);
      for (std::string line; std::getline(lines, line);) {
        line = trim(line);
        if (!line.empty() && line != ".") warnings_.add(*path + ": " + line);
      }
    }
    const auto with_kd = materials_with_kd(*bundle_.find(*path));
    for (std::size_t i = sources_.size(); i < materials->size(); ++i) {
      const std::string& material = (*materials)[i].name;
      sources_.push_back(*path);
      kd_given_.push_back(with_kd.count(material) != 0);
      // prepare_obj_text turned usemtl names with blanks into this alias.
      material_map->emplace(material_alias(material), static_cast<int>(i));
    }
    return true;
  }

  // Whether the MTL set Kd for material `id`: tinyobj fills in its own
  // defaults (0 without a texture, 0.6 with one) that cannot be told apart
  // from values written in the file.
  bool kd_given(int id) const {
    return id >= 0 && static_cast<std::size_t>(id) < kd_given_.size() && kd_given_[static_cast<std::size_t>(id)];
  }

  // The MTL that defined material `id` (the OBJ itself when unknown).
  const std::string& source_of(int id) const {
    return id >= 0 && static_cast<std::size_t>(id) < sources_.size() ? sources_[static_cast<std::size_t>(id)]
                                                                      : obj_path_;
  }

 private:
  const Bundle& bundle_;
  std::string obj_path_;
  Warnings& warnings_;
  std::vector<std::string> sources_;
  std::vector<bool> kd_given_;
};

// Only consulted on failure, so the common path does not scan the text twice.
std::size_t line_of_vertex(const std::string& text, std::size_t vertex) {
  std::size_t line = 0;
  std::size_t seen = 0;
  std::istringstream in(text);
  for (std::string s; std::getline(in, s);) {
    ++line;
    const auto first = s.find_first_not_of(" \t");
    if (first != std::string::npos && s[first] == 'v' && first + 1 < s.size() &&
        (s[first + 1] == ' ' || s[first + 1] == '\t')) {
      if (seen++ == vertex) return line;
    }
  }
  return 0;
}

struct Corner {
  int v = -1;
  int vn = -1;
  int vt = -1;
};

struct Triangle {
  Corner corner[3];
  int material = -1;  // tinyobj's id until materials are compacted, then ours
  unsigned smoothing = 0;
};

struct VertexKey {
  int v;
  int vn;
  int vt;
  std::int64_t smoothing;
  bool operator==(const VertexKey&) const = default;
};

struct VertexKeyHash {
  std::size_t operator()(const VertexKey& k) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint64_t part : {static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.v)),
                                     static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.vn)),
                                     static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.vt)),
                                     static_cast<std::uint64_t>(k.smoothing)}) {
      h = (h ^ part) * 1099511628211ull;
    }
    return static_cast<std::size_t>(h);
  }
};

struct GroupKey {
  std::uint32_t position;
  std::int64_t smoothing;
  bool operator==(const GroupKey&) const = default;
};

struct GroupKeyHash {
  std::size_t operator()(const GroupKey& k) const noexcept {
    return std::hash<std::uint64_t>()((static_cast<std::uint64_t>(k.position) << 20) ^
                                      static_cast<std::uint64_t>(k.smoothing));
  }
};

glm::vec3 sanitize_colour(const tinyobj::real_t* rgb) {
  glm::vec3 c;
  for (int i = 0; i < 3; ++i) {
    const double value = rgb[i];
    c[i] = std::isfinite(value) ? static_cast<float>(std::clamp(value, 0.0, 1.0)) : 0.8f;
  }
  return c;
}

// MTL texture statements may carry quotes or trailing options that tinyobj
// leaves in the name; try the plausible readings in turn.
std::vector<std::string> texture_name_candidates(const std::string& raw) {
  std::vector<std::string> names;
  std::string name = trim(raw);
  if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') && name.back() == name.front()) {
    name = name.substr(1, name.size() - 2);
  }
  if (!name.empty()) names.push_back(name);
  const auto space = name.find_first_of(" \t");
  if (space != std::string::npos) names.push_back(name.substr(0, space));
  return names;
}

class Importer {
 public:
  explicit Importer(const Bundle& bundle) : bundle_(bundle), obj_path_(find_obj(bundle)) {}

  Model run() {
    parse();
    check_positions();
    collect_triangles();
    if (triangles_.empty()) {
      throw ImportError(obj_path_, obj_path_ + " has no faces to render (it holds only points, lines or "
                                               "degenerate faces, or nothing at all)");
    }
    build_materials();
    build_mesh();
    model_.warnings = warnings_.take();
    return std::move(model_);
  }

 private:
  void parse() {
    std::istringstream in(prepare_obj_text(*bundle_.find(obj_path_)));
    std::string warn;
    std::string err;
    reader_ = std::make_unique<BundleMaterialReader>(bundle_, obj_path_, warnings_);
    const bool ok = tinyobj::LoadObj(&attrib_, &shapes_, &tinyobj_materials_, &warn, &err, &in, reader_.get(),
                                     /*triangulate=*/true, /*default_vcols_fallback=*/false);
    if (!ok) {
      std::string reason = trim(err.substr(0, err.find('\n')));
      if (reason.empty()) reason = "the parser gave no reason";
      throw ImportError(obj_path_, "cannot read " + obj_path_ + ": " + reason);
    }
    for (const std::string* messages : {&warn, &err}) {
      std::istringstream lines(*messages);
      for (std::string line; std::getline(lines, line);) {
        line = trim(line);
        if (line.empty() || line == ".") continue;
        std::replace(line.begin(), line.end(), '\x1f', ' ');  // undo material_alias for display
        // tinyobj silently skips such quads; a model with holes is worse
        // than a clear refusal.
        if (line.find("invalid vertex index") != std::string::npos) {
          throw ImportError(obj_path_, obj_path_ + ": a face refers to a vertex that does not exist");
        }
        // Said more precisely by BundleMaterialReader.
        if (line.find("Failed to load material file") != std::string::npos) continue;
        warnings_.add(obj_path_ + ": " + line);
      }
    }
  }

  void check_positions() {
    const auto& v = attrib_.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!std::isfinite(v[i])) {
        const std::size_t vertex = i / 3;
        const std::size_t line = line_of_vertex(*bundle_.find(obj_path_), vertex);
        throw ImportError(obj_path_, obj_path_ + ": vertex " + std::to_string(vertex + 1) +
                                         (line > 0 ? " (line " + std::to_string(line) + ")" : std::string()) +
                                         " has a coordinate that is not a finite number");
      }
    }
  }

  glm::dvec3 position(int v) const {
    const auto i = static_cast<std::size_t>(v) * 3;
    return {attrib_.vertices[i], attrib_.vertices[i + 1], attrib_.vertices[i + 2]};
  }

  void collect_triangles() {
    const auto position_count = static_cast<long long>(attrib_.vertices.size() / 3);
    const auto normal_count = static_cast<long long>(attrib_.normals.size() / 3);
    const auto texcoord_count = static_cast<long long>(attrib_.texcoords.size() / 2);
    std::size_t dropped_refs = 0;

    std::vector<Triangle> candidates;
    for (const auto& shape : shapes_) {
      std::size_t offset = 0;
      for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
        const std::size_t count = shape.mesh.num_face_vertices[f];
        // LoadObj triangulates, but a fan keeps anything it leaves intact.
        for (std::size_t k = 1; k + 1 < count; ++k) {
          Triangle tri;
          const std::size_t picks[3] = {offset, offset + k, offset + k + 1};
          for (int c = 0; c < 3; ++c) {
            const auto& idx = shape.mesh.indices[picks[c]];
            if (idx.vertex_index < 0 || idx.vertex_index >= position_count) {
              throw ImportError(obj_path_,
                                obj_path_ + ": a face" + (shape.name.empty() ? "" : " in " + quoted(shape.name)) +
                                    " refers to a vertex position that does not exist (the file defines " +
                                    std::to_string(position_count) + ")");
            }
            Corner& corner = tri.corner[c];
            corner.v = idx.vertex_index;
            corner.vn = idx.normal_index;
            corner.vt = idx.texcoord_index;
            if (corner.vn < -1 || corner.vn >= normal_count) {
              corner.vn = -1;
              ++dropped_refs;
            }
            if (corner.vt < -1 || corner.vt >= texcoord_count) {
              corner.vt = -1;
              ++dropped_refs;
            }
          }
          tri.material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
          tri.smoothing = f < shape.mesh.smoothing_group_ids.size() ? shape.mesh.smoothing_group_ids[f] : 0u;
          candidates.push_back(tri);
        }
        offset += count;
      }
    }
    if (dropped_refs > 0) {
      warnings_.add(obj_path_ + ": " + std::to_string(dropped_refs) +
                    " normal or texture-coordinate references point past the end of their lists and were ignored");
    }
    if (candidates.empty()) return;

    // The centre is taken in double from the file's own numbers, so that a
    // model far from its origin keeps full float precision once recentred.
    glm::dvec3 lo(std::numeric_limits<double>::infinity());
    glm::dvec3 hi(-std::numeric_limits<double>::infinity());
    for (const auto& tri : candidates) {
      for (const auto& corner : tri.corner) {
        lo = glm::min(lo, position(corner.v));
        hi = glm::max(hi, position(corner.v));
      }
    }
    origin_ = (lo + hi) * 0.5;
    const glm::dvec3 extent = hi - lo;
    if (!std::isfinite(extent.x) || !std::isfinite(extent.y) || !std::isfinite(extent.z) ||
        std::max({extent.x, extent.y, extent.z}) > static_cast<double>(std::numeric_limits<float>::max()) * 0.5) {
      throw ImportError(obj_path_, obj_path_ + ": the model's extent is too large to render");
    }

    std::size_t degenerate = 0;
    for (const auto& tri : candidates) {
      glm::dvec3 exact[3];
      glm::dvec3 rounded[3];
      for (int c = 0; c < 3; ++c) {
        exact[c] = position(tri.corner[c].v) - origin_;
        rounded[c] = glm::dvec3(glm::vec3(exact[c]));
      }
      // The GPU sees the float corners: a face that collapses there is as
      // degenerate as one that is flat in the file.
      if (is_degenerate_triangle(exact[0], exact[1], exact[2]) ||
          is_degenerate_triangle(rounded[0], rounded[1], rounded[2])) {
        ++degenerate;
        continue;
      }
      triangles_.push_back(tri);
    }
    if (degenerate > 0) {
      warnings_.add(obj_path_ + ": " + std::to_string(degenerate) + " degenerate (zero-area) triangle" +
                    (degenerate == 1 ? " was" : "s were") + " dropped");
    }
  }

  int texture_for(const std::string& raw_name, const std::string& material_name, const std::string& mtl_path) {
    const auto candidates = texture_name_candidates(raw_name);
    if (candidates.empty()) return -1;
    std::optional<std::string> path;
    for (const auto& name : candidates) {
      if ((path = bundle_.resolve(mtl_path, name))) break;
    }
    if (!path) {
      // Exporters often write the artist's absolute path; the file itself
      // usually travels beside the MTL.
      std::string base = candidates.front();
      std::replace(base.begin(), base.end(), '\\', '/');
      base = base.substr(base.find_last_of('/') == std::string::npos ? 0 : base.find_last_of('/') + 1);
      if (!base.empty() && base != candidates.front()) {
        path = bundle_.resolve(mtl_path, base);
        if (path) {
          warnings_.add(mtl_path + ": texture " + quoted(candidates.front()) + " of material " +
                        quoted(material_name) + " was found by its file name alone, as " + quoted(*path));
        }
      }
    }
    if (!path) {
      warnings_.add(mtl_path + ": texture " + quoted(candidates.front()) + " of material " + quoted(material_name) +
                    " is not in the bundle; the material colour is used instead");
      return -1;
    }
    if (const auto it = texture_slots_.find(*path); it != texture_slots_.end()) return it->second;
    int slot = -1;
    try {
      TextureLimits limits;
      limits.max_pixels = std::min(limits.max_pixels, texture_pixels_left_);
      model_.textures.push_back(decode_texture(*bundle_.find(*path), *path, limits));
      const Texture& texture = model_.textures.back();
      texture_pixels_left_ -= static_cast<std::uint64_t>(texture.width) * static_cast<std::uint64_t>(texture.height);
      slot = static_cast<int>(model_.textures.size()) - 1;
    } catch (const std::exception& e) {
      warnings_.add(*path + ": texture of material " + quoted(material_name) + " cannot be used: " + e.what() +
                    "; the material colour is used instead");
    }
    texture_slots_.emplace(*path, slot);
    return slot;
  }

  void build_materials() {
    std::set<int> used;
    bool default_used = false;
    for (auto& tri : triangles_) {
      if (tri.material < 0 || static_cast<std::size_t>(tri.material) >= tinyobj_materials_.size()) {
        tri.material = -1;
        default_used = true;
      } else {
        used.insert(tri.material);
      }
    }
    // Only materials that faces use: unused ones would cost texture decodes
    // and inflate the reported counts.
    std::map<int, int> slot;
    for (const int id : used) {
      const auto& source = tinyobj_materials_[static_cast<std::size_t>(id)];
      Material material;
      material.name = source.name;
      material.diffuse = sanitize_colour(source.diffuse);
      if (!source.diffuse_texname.empty()) {
        material.diffuse_texture = texture_for(source.diffuse_texname, source.name, reader_->source_of(id));
      }
      if (!reader_->kd_given(id)) {
        // Without Kd a texture shows as painted (nvdiffrec-style MTLs give
        // only map_Kd), and a plain material gets the default grey.
        material.diffuse = glm::vec3(material.diffuse_texture >= 0 ? 1.0f : 0.8f);
      }
      slot[id] = static_cast<int>(model_.materials.size());
      model_.materials.push_back(std::move(material));
    }
    if (default_used) {
      slot[-1] = static_cast<int>(model_.materials.size());
      model_.materials.push_back(Material{"default", glm::vec3(0.8f), -1});
    }
    for (auto& tri : triangles_) tri.material = slot.at(tri.material);
    std::stable_sort(triangles_.begin(), triangles_.end(),
                     [](const Triangle& a, const Triangle& b) { return a.material < b.material; });
  }

  bool normal_usable(int vn) const {
    if (vn < 0) return false;
    const auto i = static_cast<std::size_t>(vn) * 3;
    const glm::dvec3 n(attrib_.normals[i], attrib_.normals[i + 1], attrib_.normals[i + 2]);
    const double len = glm::length(n);
    return std::isfinite(len) && len > 1e-20;
  }

  // Smoothing off: corners share a vertex only with faces lying in the same
  // plane (the triangles of one polygon), keyed by the face normal's bits.
  // Negative, so it never meets a smoothing group's key.
  std::int64_t flat_key(const Triangle& tri) const {
    const glm::vec3 n(triangle_normal(position(tri.corner[0].v) - origin_, position(tri.corner[1].v) - origin_,
                                      position(tri.corner[2].v) - origin_));
    std::uint32_t bits[3];
    std::memcpy(bits, &n[0], sizeof bits);
    std::uint64_t h = 1469598103934665603ull;
    for (const auto b : bits) h = (h ^ b) * 1099511628211ull;
    return -1 - static_cast<std::int64_t>(h >> 2);
  }

  void build_mesh() {
    Mesh& mesh = model_.mesh;
    mesh.origin = origin_;

    bool smoothing_in_use = false;
    for (const auto& tri : triangles_) {
      for (const auto& corner : tri.corner) {
        if (tri.smoothing != 0 && !normal_usable(corner.vn)) smoothing_in_use = true;
      }
    }

    std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> vertex_of;
    std::vector<std::int64_t> smoothing_of_vertex;
    std::vector<bool> needs_normal;
    std::size_t bad_texcoords = 0;
    mesh.indices.reserve(triangles_.size() * 3);

    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const auto& tri = triangles_[t];
      for (const auto& corner : tri.corner) {
        const bool has_normal = normal_usable(corner.vn);
        // Vertices without a usable normal are told apart by where their
        // computed normal may average: the whole mesh, one smoothing group,
        // or (smoothing off) only their own face.
        std::int64_t smoothing = 0;
        if (!has_normal) {
          if (!smoothing_in_use) {
            smoothing = 1;
          } else if (tri.smoothing != 0) {
            smoothing = 2 + static_cast<std::int64_t>(tri.smoothing);
          } else {
            smoothing = flat_key(tri);
          }
        }
        const VertexKey key{corner.v, has_normal ? corner.vn : -1, corner.vt, smoothing};
        const auto [it, inserted] = vertex_of.emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
        if (inserted) {
          if (mesh.positions.size() >= std::numeric_limits<std::uint32_t>::max()) {
            throw ImportError(obj_path_, obj_path_ + " has too many vertices");
          }
          mesh.positions.emplace_back(position(corner.v) - origin_);
          glm::vec3 normal(0.0f);
          if (has_normal) {
            const auto i = static_cast<std::size_t>(corner.vn) * 3;
            normal = glm::vec3(glm::normalize(
                glm::dvec3(attrib_.normals[i], attrib_.normals[i + 1], attrib_.normals[i + 2])));
          }
          mesh.normals.push_back(normal);
          glm::vec2 uv(0.0f);
          if (corner.vt >= 0) {
            const auto i = static_cast<std::size_t>(corner.vt) * 2;
            const glm::dvec2 raw(attrib_.texcoords[i], attrib_.texcoords[i + 1]);
            if (std::isfinite(raw.x) && std::isfinite(raw.y) && std::abs(raw.x) < 1e30 && std::abs(raw.y) < 1e30) {
              uv = glm::vec2(raw);
            } else {
              ++bad_texcoords;
            }
          }
          mesh.texcoords.push_back(uv);
          smoothing_of_vertex.push_back(smoothing);
          needs_normal.push_back(!has_normal);
        }
        mesh.indices.push_back(it->second);
      }
    }
    if (bad_texcoords > 0) {
      warnings_.add(obj_path_ + ": " + std::to_string(bad_texcoords) +
                    " texture coordinates were not finite numbers and were set to 0");
    }

    if (std::find(needs_normal.begin(), needs_normal.end(), true) != needs_normal.end()) {
      const auto position_class = group_by_position(mesh.positions);
      std::unordered_map<GroupKey, std::uint32_t, GroupKeyHash> group_ids;
      std::vector<std::uint32_t> groups(mesh.positions.size());
      for (std::size_t v = 0; v < groups.size(); ++v) {
        // A vertex that brought its own normal forms a group of its own
        // (its computed normal is discarded anyway).
        const GroupKey key = needs_normal[v]
                                 ? GroupKey{position_class[v], smoothing_of_vertex[v]}
                                 : GroupKey{static_cast<std::uint32_t>(v), std::numeric_limits<std::int64_t>::min()};
        groups[v] = group_ids.emplace(key, static_cast<std::uint32_t>(group_ids.size())).first->second;
      }
      const auto computed = compute_grouped_normals(mesh.positions, mesh.indices, groups);
      for (std::size_t v = 0; v < groups.size(); ++v) {
        if (needs_normal[v]) mesh.normals[v] = computed[v];
      }
    }

    mesh.outline_normals = compute_outline_normals(mesh.positions, mesh.indices, mesh.normals);
    mesh.bounds = compute_bounds(mesh.positions);

    for (std::size_t t = 0; t < triangles_.size();) {
      Submesh sub;
      sub.material = triangles_[t].material;
      sub.first_index = static_cast<std::uint32_t>(t * 3);
      std::size_t end = t;
      while (end < triangles_.size() && triangles_[end].material == sub.material) ++end;
      sub.index_count = static_cast<std::uint32_t>((end - t) * 3);
      mesh.submeshes.push_back(sub);
      t = end;
    }
  }

  const Bundle& bundle_;
  std::string obj_path_;
  Warnings warnings_;
  std::unique_ptr<BundleMaterialReader> reader_;
  tinyobj::attrib_t attrib_;
  std::vector<tinyobj::shape_t> shapes_;
  std::vector<tinyobj::material_t> tinyobj_materials_;
  std::vector<Triangle> triangles_;
  glm::dvec3 origin_{0.0};
  std::map<std::string, int> texture_slots_;
  // All textures of one model together: many materials each naming a large
  // image must not add up to more memory than one upload deserves (1 GiB).
  std::uint64_t texture_pixels_left_ = 256ull * 1024 * 1024;
  Model model_;
};

}  // namespace

Model import_obj_bundle(const Bundle& bundle) { return Importer(bundle).run(); }

}  // namespace toond::scene
