#include "glb_from_obj.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "bundle_paths/bundle_path.h"
#include "bundle_paths/name_index.h"
#include "bundle_paths/statement_names.h"
#include "cli_args.h"
#include "glb/glb_container.h"
#include "obj_text/mtl_material.h"
#include "obj_text/obj_text.h"

namespace toond::cli {
namespace {

using nlohmann::json;

// The roughness of a material with a highlight: under 1, the daemon reads
// the material as having one (scene::Material::matte).
constexpr double kGlossyRoughness = 0.5;

// The scanned files, found as the daemon finds a bundle's
// (bundle_paths::resolve_reference, then NameIndex's case rule), so the
// .glb holds exactly what `toon upload` would have sent.
class ScannedFiles {
 public:
  explicit ScannedFiles(const BundleScan& scan) {
    for (const BundleFile& f : scan.files) {
      names_.add(f.name);
      by_name_.emplace(f.name, &f);
    }
  }

  // The file `reference` names, read from bundle file `from`.
  const BundleFile* resolve(std::string_view from, std::string_view reference) const {
    const bundle_paths::Reading reading = bundle_paths::resolve_reference(from, reference);
    if (reading.refusal != bundle_paths::Refusal::none) return nullptr;
    const std::optional<std::string> name = names_.find(reading.path);
    return name ? by_name_.at(*name) : nullptr;
  }

  // The first file a texture statement of MTL `mtl` may mean.
  const BundleFile* texture(std::string_view mtl, std::string_view statement) const {
    for (const bundle_paths::TextureName& candidate : bundle_paths::texture_names(statement)) {
      if (const BundleFile* file = resolve(mtl, candidate.name)) return file;
    }
    return nullptr;
  }

 private:
  bundle_paths::NameIndex names_;
  std::map<std::string, const BundleFile*> by_name_;
};

// What an MTL says of a material, and the MTL it says it in: texture names
// are read from the MTL's folder.
struct ReadMaterial {
  std::string mtl;
  obj_text::MtlMaterial said;
};

// Serves `mtllib` lines from the scan and reads their materials through
// the reader the daemon's OBJ importer uses (obj_text::read_mtl).
class ScannedMaterials : public tinyobj::MaterialReader {
 public:
  ScannedMaterials(const ScannedFiles& files, std::string obj) : files_(files), obj_(std::move(obj)) {}

  // `line` is a whole mtllib line (prepare_obj_text keeps tinyobj from
  // cutting it), read as the daemon reads it.
  bool operator()(const std::string& line, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* by_name, std::string* warn, std::string* err) override {
    const auto sent = [&](const std::string& name) { return files_.resolve(obj_, name) != nullptr; };
    for (const std::string& reference : bundle_paths::mtllib_names(line, sent)) {
      const BundleFile* mtl = files_.resolve(obj_, reference);
      if (!mtl) continue;
      for (obj_text::MtlMaterial& said : obj_text::read_mtl(mtl->content, materials, by_name, warn, err)) {
        read.push_back({mtl->name, std::move(said)});
      }
    }
    return true;
  }

  std::vector<ReadMaterial> read;  // in tinyobj's order

 private:
  const ScannedFiles& files_;
  std::string obj_;
};

struct ReadObj {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<ReadMaterial> materials;
};

// The OBJ read as toond's importer reads it: its text prepared alike, then
// triangulated by tinyobj, so a quad is split along the same diagonal.
ReadObj read_obj(const BundleFile& obj, const ScannedFiles& files) {
  obj_text::ObjTextFindings findings;
  std::istringstream in(obj_text::prepare_obj_text(obj.content, &findings));
  if (findings.missing_vertex_line != 0) {
    throw UsageError("cannot write " + obj.name + " as glTF: a face names a missing vertex (line " +
                     std::to_string(findings.missing_vertex_line) + ")");
  }
  ReadObj read;
  ScannedMaterials reader(files, obj.name);
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  if (!tinyobj::LoadObj(&read.attrib, &read.shapes, &materials, &warn, &err, &in, &reader, true, false)) {
    throw UsageError("cannot write " + obj.name + " as glTF: " + (err.empty() ? "it does not parse" : err));
  }
  read.materials = std::move(reader.read);
  return read;
}

// Positions are stored in float about the middle of the model and the node
// moves them back in double, so a model far from the origin keeps the
// precision toond gives its OBJ.
std::array<double, 3> middle_of(const std::vector<tinyobj::real_t>& vertices) {
  std::array<double, 3> centre{};
  if (vertices.empty()) return centre;
  for (std::size_t k = 0; k < 3; ++k) {
    double low = vertices[k], high = low;
    for (std::size_t v = k; v < vertices.size(); v += 3) {
      low = std::min<double>(low, vertices[v]);
      high = std::max<double>(high, vertices[v]);
    }
    centre[k] = low / 2 + high / 2;
  }
  return centre;
}

struct Primitive {
  std::vector<float> positions, normals, texcoords;
  std::vector<std::uint32_t> indices;
  std::map<std::array<int, 3>, std::uint32_t> vertex_of_corner;
  bool every_normal = true;
  bool every_texcoord = true;
};

// One primitive per material (keyed by material id, -1: none, so they come
// out in material order), a vertex per distinct position/UV/normal corner.
class PrimitiveBuilder {
 public:
  PrimitiveBuilder(const ReadObj& obj, const std::string& name, const std::array<double, 3>& centre)
      : attrib_(obj.attrib), materials_(obj.materials.size()), name_(name), centre_(centre) {}

  void add(const tinyobj::shape_t& shape) {
    std::size_t corner = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t corners = shape.mesh.num_face_vertices[f];
      const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      Primitive& p = primitives[material >= 0 && static_cast<std::size_t>(material) < materials_ ? material : -1];
      std::vector<std::uint32_t> face;
      for (std::size_t c = 0; c < corners; ++c, ++corner) face.push_back(vertex(p, shape.mesh.indices[corner]));
      // tinyobj triangulated; the fan keeps anything it left whole.
      for (std::size_t c = 1; c + 1 < face.size(); ++c) {
        p.indices.insert(p.indices.end(), {face[0], face[c], face[c + 1]});
      }
    }
  }

  std::map<int, Primitive> primitives;

 private:
  static bool in_range(int index, std::size_t size, int components) {
    return index >= 0 && static_cast<std::size_t>(index) < size / static_cast<std::size_t>(components);
  }

  // The primitive's vertex for corner `i`, added when it is new.
  std::uint32_t vertex(Primitive& p, const tinyobj::index_t& i) {
    if (!in_range(i.vertex_index, attrib_.vertices.size(), 3)) {
      throw UsageError("cannot write " + name_ + " as glTF: a face names a missing vertex");
    }
    const bool has_normal = in_range(i.normal_index, attrib_.normals.size(), 3);
    const bool has_texcoord = in_range(i.texcoord_index, attrib_.texcoords.size(), 2);
    const std::array<int, 3> key{i.vertex_index, has_texcoord ? i.texcoord_index : -1,
                                 has_normal ? i.normal_index : -1};
    const auto [it, added] = p.vertex_of_corner.try_emplace(key, static_cast<std::uint32_t>(p.vertex_of_corner.size()));
    if (!added) return it->second;
    const auto v = static_cast<std::size_t>(i.vertex_index);
    const auto n = static_cast<std::size_t>(i.normal_index);
    const auto t = static_cast<std::size_t>(i.texcoord_index);
    for (std::size_t k = 0; k < 3; ++k) {
      p.positions.push_back(static_cast<float>(attrib_.vertices[3 * v + k] - centre_[k]));
      p.normals.push_back(has_normal ? static_cast<float>(attrib_.normals[3 * n + k]) : 0.0f);
    }
    // glTF's v runs down the image.
    p.texcoords.push_back(has_texcoord ? static_cast<float>(attrib_.texcoords[2 * t]) : 0.0f);
    p.texcoords.push_back(has_texcoord ? static_cast<float>(1.0 - attrib_.texcoords[2 * t + 1]) : 0.0f);
    p.every_normal = p.every_normal && has_normal;
    p.every_texcoord = p.every_texcoord && has_texcoord;
    return it->second;
  }

  const tinyobj::attrib_t& attrib_;
  std::size_t materials_;
  const std::string& name_;
  std::array<double, 3> centre_;
};

std::string image_media_type(const std::string& name) {
  std::string n = name;
  for (char& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return n.ends_with(".jpg") || n.ends_with(".jpeg") ? "image/jpeg" : "image/png";
}

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// The glTF document and its one binary buffer, each view 4-byte aligned as
// glTF requires of float and uint32 accessors.
class GlbWriter {
 public:
  explicit GlbWriter(const std::array<double, 3>& centre)
      : document_(json{{"asset", {{"version", "2.0"}, {"generator", "toon gallery (glb_from_obj)"}}},
                       {"scene", 0},
                       {"scenes", json::array({{{"nodes", {0}}}})},
                       {"nodes", json::array({{{"mesh", 0}, {"translation", centre}}})},
                       {"bufferViews", json::array()},
                       {"accessors", json::array()},
                       {"materials", json::array()}}) {}

  // A primitive drawn in `material` (null: faces with no material) as the
  // daemon draws the OBJ's: not metal; fully rough only where the MTL says
  // the material has no highlight; Kd, map_Kd and d as the MTL gives them.
  void add(const Primitive& p, const ReadMaterial* material, const BundleFile* texture) {
    const obj_text::MtlMaterial said = material ? material->said : obj_text::MtlMaterial{};
    const obj_text::Rgb colour =
        material ? obj_text::base_colour(said, texture != nullptr) : obj_text::plain_colour(false);
    const float opacity = said.opacity.value_or(1.0f);
    json pbr = {{"metallicFactor", 0.0},
                {"roughnessFactor", said.matte ? 1.0 : kGlossyRoughness},
                {"baseColorFactor", {colour[0], colour[1], colour[2], opacity}}};
    if (texture) pbr["baseColorTexture"] = {{"index", texture_for(*texture)}};
    json written = {{"pbrMetallicRoughness", pbr}};
    if (said.opacity) written["alphaMode"] = "BLEND";
    document_["materials"].push_back(std::move(written));
    json attributes = {{"POSITION", accessor(p.positions, 3, kFloat, "VEC3", kArrayBuffer)}};
    set_bounds(document_["accessors"].back(), p.positions);
    if (p.every_normal) attributes["NORMAL"] = accessor(p.normals, 3, kFloat, "VEC3", kArrayBuffer);
    if (p.every_texcoord) attributes["TEXCOORD_0"] = accessor(p.texcoords, 2, kFloat, "VEC2", kArrayBuffer);
    const int indices = accessor(p.indices, 1, kUnsignedInt, "SCALAR", kElementArrayBuffer);
    primitives_.push_back(
        {{"attributes", attributes}, {"indices", indices}, {"material", document_["materials"].size() - 1}});
  }

  std::string finish() {
    document_["meshes"] = json::array({{{"primitives", primitives_}}});
    document_["buffers"] = json::array({{{"byteLength", bin_.size()}}});
    return glb::glb_container(document_.dump(), bin_);
  }

 private:
  int view(const void* data, std::size_t bytes, int target) {
    while (bin_.size() % 4) bin_.push_back('\0');
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}};
    if (target) v["target"] = target;
    bin_.append(static_cast<const char*>(data), bytes);
    document_["bufferViews"].push_back(std::move(v));
    return static_cast<int>(document_["bufferViews"].size() - 1);
  }

  template <typename T>
  int accessor(const std::vector<T>& values, int components, int component_type, const char* type, int target) {
    const std::size_t count = values.size() / static_cast<std::size_t>(components);
    json a = {{"bufferView", view(values.data(), values.size() * sizeof(T), target)},
              {"componentType", component_type},
              {"count", count},
              {"type", type}};
    document_["accessors"].push_back(std::move(a));
    return static_cast<int>(document_["accessors"].size() - 1);
  }

  // glTF requires a POSITION accessor's min and max.
  static void set_bounds(json& accessor, const std::vector<float>& positions) {
    std::array<float, 3> low, high;
    low.fill(std::numeric_limits<float>::max());
    high.fill(std::numeric_limits<float>::lowest());
    for (std::size_t v = 0; v < positions.size(); ++v) {
      low[v % 3] = std::min(low[v % 3], positions[v]);
      high[v % 3] = std::max(high[v % 3], positions[v]);
    }
    accessor["min"] = low;
    accessor["max"] = high;
  }

  // Each image file stored once, however many materials use it.
  int texture_for(const BundleFile& file) {
    const auto [it, added] = texture_of_file_.try_emplace(file.name, static_cast<int>(texture_of_file_.size()));
    if (added) {
      const int image_view = view(file.content.data(), file.content.size(), 0);
      document_["images"].push_back({{"bufferView", image_view}, {"mimeType", image_media_type(file.name)}});
      document_["textures"].push_back({{"source", it->second}});
    }
    return it->second;
  }

  json document_;
  json primitives_ = json::array();
  std::string bin_;
  std::map<std::string, int> texture_of_file_;
};

}  // namespace

std::string glb_from_obj(const BundleScan& scan) {
  if (scan.files.empty()) throw UsageError("no OBJ to write as glTF");
  const BundleFile& obj = scan.files.front();
  const ScannedFiles files(scan);
  const ReadObj read = read_obj(obj, files);
  const std::array<double, 3> centre = middle_of(read.attrib.vertices);
  PrimitiveBuilder builder(read, obj.name, centre);
  for (const tinyobj::shape_t& shape : read.shapes) builder.add(shape);
  std::erase_if(builder.primitives, [](const auto& entry) { return entry.second.indices.empty(); });
  if (builder.primitives.empty()) throw UsageError("cannot write " + obj.name + " as glTF: it has no faces");
  GlbWriter writer(centre);
  for (const auto& [material_id, p] : builder.primitives) {
    const ReadMaterial* material = material_id >= 0 ? &read.materials[static_cast<std::size_t>(material_id)] : nullptr;
    const BundleFile* texture = material && !material->said.colour_map.empty()
                                    ? files.texture(material->mtl, material->said.colour_map)
                                    : nullptr;
    writer.add(p, material, texture);
  }
  return writer.finish();
}

}  // namespace toond::cli
