#include "glb_from_obj.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "glb/glb_container.h"

namespace toond::cli {
namespace {

using nlohmann::json;

// toond's colour for an MTL material without Kd and no texture, and for
// faces without a material (server/scene/import/obj_import.cpp).
constexpr float kPlainGrey = 0.8f;
// The roughness of a material with a highlight: under 1, the daemon reads
// the material as having one (scene::Material::matte).
constexpr double kGlossyRoughness = 0.5;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string folder_of(const std::string& bundle_path) {
  const auto slash = bundle_path.rfind('/');
  return slash == std::string::npos ? std::string() : bundle_path.substr(0, slash + 1);
}

// tinyobj cannot say whether Kd was written (it makes up 0.6 beside a
// map_Kd), and toond's colour for a material without one differs; so the
// MTL text is asked directly.
std::set<std::string> materials_with(const std::string& mtl_text, const std::string& wanted) {
  std::set<std::string> named;
  std::string current;
  std::istringstream lines(mtl_text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "newmtl") {
      std::getline(words >> std::ws, current);
      while (!current.empty() && std::isspace(static_cast<unsigned char>(current.back()))) current.pop_back();
    } else if (keyword == wanted) {
      named.insert(current);
    }
  }
  return named;
}

// MTL files come from the scan, not the disk, so the .glb holds exactly
// what `toon upload` would have sent.
class ScannedMaterials : public tinyobj::MaterialReader {
 public:
  explicit ScannedMaterials(const BundleScan& scan) : scan_(scan) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* by_name, std::string* warn, std::string* err) override {
    const BundleFile* mtl = find(name);
    if (!mtl) {
      if (warn) *warn += "material library " + name + " was not sent\n";
      return false;
    }
    const std::size_t first = materials->size();
    std::istringstream in(mtl->content);
    tinyobj::LoadMtl(by_name, materials, &in, warn, err);
    const std::set<std::string> with_kd = materials_with(mtl->content, "Kd");
    const std::set<std::string> with_ks = materials_with(mtl->content, "Ks");
    const std::set<std::string> with_illum = materials_with(mtl->content, "illum");
    for (std::size_t i = first; i < materials->size(); ++i) {
      const tinyobj::material_t& material = (*materials)[i];
      folders.push_back(folder_of(mtl->name));
      kd_given.push_back(with_kd.count(material.name) > 0);
      // As the daemon reads an MTL (scene::Material::matte).
      const bool no_ks = with_ks.count(material.name) > 0 && material.specular[0] == 0 && material.specular[1] == 0 &&
                         material.specular[2] == 0;
      const bool flat_illum = with_illum.count(material.name) > 0 && (material.illum == 0 || material.illum == 1);
      matte.push_back(no_ks || flat_illum);
    }
    return true;
  }

  // The scanned file at bundle path `name` (resolved as the daemon does:
  // `\` as `/`, any case when the exact name is not there).
  const BundleFile* find(std::string name) const {
    std::replace(name.begin(), name.end(), '\\', '/');
    while (name.rfind("./", 0) == 0) name.erase(0, 2);
    for (const BundleFile& f : scan_.files) {
      if (f.name == name) return &f;
    }
    for (const BundleFile& f : scan_.files) {
      if (lower(f.name) == lower(name)) return &f;
    }
    return nullptr;
  }

  // Per material, in tinyobj's order: its MTL's folder, whether it had Kd,
  // and whether it says it has no highlight.
  std::vector<std::string> folders;
  std::vector<bool> kd_given;
  std::vector<bool> matte;

 private:
  const BundleScan& scan_;
};

struct Primitive {
  std::vector<float> positions, normals, texcoords;
  std::vector<std::uint32_t> indices;
  std::map<std::array<int, 3>, std::uint32_t> vertex_of_corner;
  bool every_normal = true;
  bool every_texcoord = true;
};

std::string image_media_type(const std::string& name) {
  const std::string n = lower(name);
  return n.ends_with(".jpg") || n.ends_with(".jpeg") ? "image/jpeg" : "image/png";
}

// The one binary buffer, each view 4-byte aligned as glTF requires of
// float and uint32 accessors.
class BinaryBuffer {
 public:
  explicit BinaryBuffer(json& document) : document_(document) {}

  int view(const void* data, std::size_t bytes, int target) {
    while (bin.size() % 4) bin.push_back('\0');
    json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (target) v["target"] = target;
    bin.append(static_cast<const char*>(data), bytes);
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

  std::string bin;

 private:
  json& document_;
};

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

}  // namespace

std::string glb_from_obj(const BundleScan& scan) {
  if (scan.files.empty()) throw UsageError("no OBJ to write as glTF");
  const BundleFile& obj = scan.files.front();
  ScannedMaterials materials_reader(scan);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream in(obj.content);
  // Triangulated by tinyobj as toond's importer has it, so a quad is split
  // along the same diagonal; the fan below keeps anything it leaves whole.
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &materials_reader, true, false)) {
    throw UsageError("cannot write " + obj.name + " as glTF: " + (err.empty() ? "it does not parse" : err));
  }
  // Positions are stored in float about the middle of the model and the
  // node moves them back in double, so a model far from the origin keeps
  // the precision toond gives its OBJ.
  std::array<double, 3> centre{};
  if (!attrib.vertices.empty()) {
    for (int k = 0; k < 3; ++k) {
      double low = attrib.vertices[static_cast<std::size_t>(k)], high = low;
      for (std::size_t v = static_cast<std::size_t>(k); v < attrib.vertices.size(); v += 3) {
        low = std::min<double>(low, attrib.vertices[v]);
        high = std::max<double>(high, attrib.vertices[v]);
      }
      centre[static_cast<std::size_t>(k)] = low / 2 + high / 2;
    }
  }

  // Keyed by material id (-1: none), so primitives come out in material order.
  std::map<int, Primitive> primitives;
  const auto in_range = [](int index, std::size_t size, int components) {
    return index >= 0 && static_cast<std::size_t>(index) < size / static_cast<std::size_t>(components);
  };
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t corner = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t corners = shape.mesh.num_face_vertices[f];
      const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      Primitive& p = primitives[material >= 0 && static_cast<std::size_t>(material) < materials.size() ? material : -1];
      std::vector<std::uint32_t> face;
      for (std::size_t c = 0; c < corners; ++c, ++corner) {
        const tinyobj::index_t& i = shape.mesh.indices[corner];
        if (!in_range(i.vertex_index, attrib.vertices.size(), 3)) {
          throw UsageError("cannot write " + obj.name + " as glTF: a face names a missing vertex");
        }
        const bool has_normal = in_range(i.normal_index, attrib.normals.size(), 3);
        const bool has_texcoord = in_range(i.texcoord_index, attrib.texcoords.size(), 2);
        const std::array<int, 3> key{i.vertex_index, has_texcoord ? i.texcoord_index : -1,
                                     has_normal ? i.normal_index : -1};
        const auto [it, added] =
            p.vertex_of_corner.try_emplace(key, static_cast<std::uint32_t>(p.vertex_of_corner.size()));
        if (added) {
          const auto v = static_cast<std::size_t>(i.vertex_index);
          const auto n = static_cast<std::size_t>(i.normal_index);
          const auto t = static_cast<std::size_t>(i.texcoord_index);
          for (std::size_t k = 0; k < 3; ++k) {
            p.positions.push_back(static_cast<float>(attrib.vertices[3 * v + k] - centre[k]));
            p.normals.push_back(has_normal ? static_cast<float>(attrib.normals[3 * n + k]) : 0.0f);
          }
          p.texcoords.push_back(has_texcoord ? static_cast<float>(attrib.texcoords[2 * t]) : 0.0f);
          p.texcoords.push_back(has_texcoord ? static_cast<float>(1.0 - attrib.texcoords[2 * t + 1]) : 0.0f);
          p.every_normal = p.every_normal && has_normal;
          p.every_texcoord = p.every_texcoord && has_texcoord;
        }
        face.push_back(it->second);
      }
      for (std::size_t c = 1; c + 1 < face.size(); ++c) {
        p.indices.insert(p.indices.end(), {face[0], face[c], face[c + 1]});
      }
    }
  }
  std::erase_if(primitives, [](const auto& entry) { return entry.second.indices.empty(); });
  if (primitives.empty()) throw UsageError("cannot write " + obj.name + " as glTF: it has no faces");

  json document = {{"asset", {{"version", "2.0"}, {"generator", "toon gallery (glb_from_obj)"}}},
                   {"scene", 0},
                   {"scenes", json::array({{{"nodes", {0}}}})},
                   {"nodes", json::array({{{"mesh", 0}, {"translation", centre}}})},
                   {"bufferViews", json::array()},
                   {"accessors", json::array()},
                   {"materials", json::array()}};
  BinaryBuffer buffer(document);
  std::map<std::string, int> texture_of_file;
  const auto texture_for = [&](const BundleFile& file) {
    const auto [it, added] = texture_of_file.try_emplace(file.name, static_cast<int>(texture_of_file.size()));
    if (added) {
      const int view = buffer.view(file.content.data(), file.content.size(), 0);
      document["images"].push_back({{"bufferView", view}, {"mimeType", image_media_type(file.name)}});
      document["textures"].push_back({{"source", it->second}});
    }
    return it->second;
  };

  json mesh_primitives = json::array();
  for (const auto& [material_id, p] : primitives) {
    // Not metal; fully rough only where the MTL says the material has no
    // highlight, so the daemon draws the .glb's highlights as the OBJ's.
    json pbr = {{"metallicFactor", 0.0}, {"roughnessFactor", kGlossyRoughness}};
    std::array<float, 3> factor{kPlainGrey, kPlainGrey, kPlainGrey};
    if (material_id >= 0 && materials_reader.matte[static_cast<std::size_t>(material_id)]) {
      pbr["roughnessFactor"] = 1.0;
    }
    if (material_id >= 0) {
      const auto m = static_cast<std::size_t>(material_id);
      const tinyobj::material_t& source = materials[m];
      const BundleFile* texture = source.diffuse_texname.empty()
                                      ? nullptr
                                      : materials_reader.find(materials_reader.folders[m] + source.diffuse_texname);
      if (texture) pbr["baseColorTexture"] = {{"index", texture_for(*texture)}};
      if (materials_reader.kd_given[m]) {
        for (std::size_t k = 0; k < 3; ++k) factor[k] = static_cast<float>(source.diffuse[k]);
      } else if (!source.diffuse_texname.empty()) {
        factor = {1.0f, 1.0f, 1.0f};
      }
    }
    pbr["baseColorFactor"] = {factor[0], factor[1], factor[2], 1.0f};
    document["materials"].push_back({{"pbrMetallicRoughness", pbr}});

    std::array<float, 3> low{}, high{};
    for (int k = 0; k < 3; ++k) {
      low[k] = std::numeric_limits<float>::max();
      high[k] = std::numeric_limits<float>::lowest();
    }
    for (std::size_t v = 0; v < p.positions.size(); ++v) {
      low[v % 3] = std::min(low[v % 3], p.positions[v]);
      high[v % 3] = std::max(high[v % 3], p.positions[v]);
    }
    json attributes = {{"POSITION", buffer.accessor(p.positions, 3, kFloat, "VEC3", kArrayBuffer)}};
    document["accessors"].back()["min"] = low;
    document["accessors"].back()["max"] = high;
    if (p.every_normal) attributes["NORMAL"] = buffer.accessor(p.normals, 3, kFloat, "VEC3", kArrayBuffer);
    if (p.every_texcoord) attributes["TEXCOORD_0"] = buffer.accessor(p.texcoords, 2, kFloat, "VEC2", kArrayBuffer);
    const int indices = buffer.accessor(p.indices, 1, kUnsignedInt, "SCALAR", kElementArrayBuffer);
    mesh_primitives.push_back(
        {{"attributes", attributes}, {"indices", indices}, {"material", document["materials"].size() - 1}});
  }
  document["meshes"] = json::array({{{"primitives", mesh_primitives}}});
  document["buffers"] = json::array({{{"byteLength", buffer.bin.size()}}});
  return glb::glb_container(document.dump(), buffer.bin);
}

}  // namespace toond::cli
