#include "support/gltf_writer.h"

#include <algorithm>
#include <cstring>

#include <openssl/evp.h>

#include "glb/glb_container.h"

namespace toond::test {
namespace {

using nlohmann::json;

class BinaryWriter {
 public:
  // Appends `bytes` as a buffer view (4-byte aligned) and returns its index.
  int add_view(const void* bytes, std::size_t size, json& views, std::optional<int> target = std::nullopt) {
    while (bin.size() % 4 != 0) bin.push_back('\0');
    json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
    if (target) view["target"] = *target;
    bin.append(static_cast<const char*>(bytes), size);
    views.push_back(view);
    return static_cast<int>(views.size()) - 1;
  }
  std::string bin;
};

template <typename T>
int add_accessor(BinaryWriter& writer, json& doc, const std::vector<T>& values, const char* type, int component_type,
                 int components, bool bounds) {
  const int view = writer.add_view(values.data(), values.size() * sizeof(T), doc["bufferViews"]);
  json accessor = {{"bufferView", view}, {"componentType", component_type}, {"count", values.size()}, {"type", type}};
  if (bounds && !values.empty()) {
    std::vector<float> lo(static_cast<std::size_t>(components), 1e30f);
    std::vector<float> hi(static_cast<std::size_t>(components), -1e30f);
    for (const T& v : values) {
      for (int c = 0; c < components; ++c) {
        lo[static_cast<std::size_t>(c)] = std::min(lo[static_cast<std::size_t>(c)], v[c]);
        hi[static_cast<std::size_t>(c)] = std::max(hi[static_cast<std::size_t>(c)], v[c]);
      }
    }
    accessor["min"] = lo;
    accessor["max"] = hi;
  }
  doc["accessors"].push_back(accessor);
  return static_cast<int>(doc["accessors"].size()) - 1;
}

std::string base64(const std::string& bytes) {
  std::string out(4 * ((bytes.size() + 2) / 3) + 1, '\0');
  const int n = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()),
                                reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()));
  out.resize(static_cast<std::size_t>(n));
  return out;
}

}  // namespace

std::size_t components_of(const std::string& type) {
  return type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 16;
}

void list_extension(json& doc, const char* list, const char* extension) {
  json& names = doc[list];
  if (!names.is_array()) names = json::array();
  if (std::find(names.begin(), names.end(), extension) == names.end()) names.push_back(extension);
}

std::string data_uri(const std::string& bytes, const std::string& media_type) {
  return "data:" + media_type + ";base64," + base64(bytes);
}

GltfParts build_gltf(const GltfDocument& document) {
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "toond tests"}}},
              {"accessors", json::array()},
              {"bufferViews", json::array()},
              {"meshes", json::array()},
              {"nodes", json::array()}};
  BinaryWriter writer;
  for (const auto& primitives : document.meshes) {
    json mesh = {{"primitives", json::array()}};
    for (const GltfPrimitive& p : primitives) {
      json attributes = {{"POSITION", add_accessor(writer, doc, p.positions, "VEC3", 5126, 3, true)}};
      if (!p.normals.empty()) attributes["NORMAL"] = add_accessor(writer, doc, p.normals, "VEC3", 5126, 3, false);
      if (!p.texcoords.empty())
        attributes["TEXCOORD_0"] = add_accessor(writer, doc, p.texcoords, "VEC2", 5126, 2, false);
      if (!p.tangents.empty()) attributes["TANGENT"] = add_accessor(writer, doc, p.tangents, "VEC4", 5126, 4, false);
      if (!p.colours.empty()) attributes["COLOR_0"] = add_accessor(writer, doc, p.colours, "VEC4", 5126, 4, false);
      json primitive = {{"attributes", attributes}, {"mode", p.mode}};
      if (!p.indices.empty()) {
        const int view = writer.add_view(p.indices.data(), p.indices.size() * 4, doc["bufferViews"], 34963);
        doc["accessors"].push_back(
            {{"bufferView", view}, {"componentType", 5125}, {"count", p.indices.size()}, {"type", "SCALAR"}});
        primitive["indices"] = doc["accessors"].size() - 1;
      }
      if (p.material >= 0) primitive["material"] = p.material;
      mesh["primitives"].push_back(primitive);
    }
    doc["meshes"].push_back(mesh);
  }
  std::vector<GltfNode> nodes = document.nodes;
  std::vector<int> roots = document.scene_roots;
  if (nodes.empty()) {
    for (std::size_t m = 0; m < document.meshes.size(); ++m) {
      GltfNode node;
      node.mesh = static_cast<int>(m);
      nodes.push_back(node);
      roots.push_back(static_cast<int>(m));
    }
  }
  for (const GltfNode& n : nodes) {
    json node = json::object();
    if (n.mesh >= 0) node["mesh"] = n.mesh;
    if (!n.children.empty()) node["children"] = n.children;
    if (n.matrix) node["matrix"] = *n.matrix;
    if (n.translation) node["translation"] = {n.translation->x, n.translation->y, n.translation->z};
    if (n.rotation) node["rotation"] = {n.rotation->x, n.rotation->y, n.rotation->z, n.rotation->w};
    if (n.scale) node["scale"] = {n.scale->x, n.scale->y, n.scale->z};
    doc["nodes"].push_back(node);
  }
  doc["scenes"] = json::array({{{"nodes", roots}}});
  doc["scene"] = 0;
  for (const GltfImage& image : document.images) {
    const int view = writer.add_view(image.bytes.data(), image.bytes.size(), doc["bufferViews"]);
    doc["images"].push_back({{"bufferView", view}, {"mimeType", image.mime_type}});
    doc["textures"].push_back({{"source", doc["images"].size() - 1}});
  }
  for (const GltfMaterial& m : document.materials) {
    json material = {{"pbrMetallicRoughness",
                      {{"baseColorFactor", {m.base_colour.r, m.base_colour.g, m.base_colour.b, m.base_colour.a}}}}};
    if (m.base_colour_image >= 0)
      material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", m.base_colour_image}};
    if (m.normal_image >= 0) material["normalTexture"] = {{"index", m.normal_image}};
    material.merge_patch(m.json);
    doc["materials"].push_back(material);
  }
  while (writer.bin.size() % 4 != 0) writer.bin.push_back('\0');
  doc["buffers"] = json::array({{{"byteLength", writer.bin.size()}}});
  return {doc, writer.bin};
}

GltfFiles pack_gltf(const GltfParts& parts, GltfForm form, const std::string& stem,
                    const std::vector<GltfImage>& images) {
  json doc = parts.json;
  switch (form) {
    case GltfForm::Glb:
      return {{stem + ".glb", glb::glb_container(doc.dump(), parts.bin)}};
    case GltfForm::DataUris:
      doc["buffers"][0]["uri"] = data_uri(parts.bin, "application/octet-stream");
      return {{stem + ".gltf", doc.dump(1)}};
    case GltfForm::SeparateFiles: {
      GltfFiles files;
      doc["buffers"][0]["uri"] = stem + ".bin";
      // Images become files of their own beside the .gltf.
      if (doc.contains("images")) {
        for (std::size_t i = 0; i < doc["images"].size() && i < images.size(); ++i) {
          doc["images"][i] = {{"uri", images[i].file_name}};
          files.emplace_back(images[i].file_name, images[i].bytes);
        }
      }
      files.emplace_back(stem + ".gltf", doc.dump(1));
      files.emplace_back(stem + ".bin", parts.bin);
      return files;
    }
  }
  return {};
}

GltfFiles write_gltf(const GltfDocument& document, GltfForm form, const std::string& stem) {
  return pack_gltf(build_gltf(document), form, stem, document.images);
}

}  // namespace toond::test
