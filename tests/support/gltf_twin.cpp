#include "support/gltf_twin.h"

#include <cmath>
#include <map>

namespace toond::test {
namespace {

float srgb_decoded(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

std::string media_type_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  return ext == "jpg" || ext == "jpeg" || ext == "JPG" ? "image/jpeg" : "image/png";
}

}  // namespace

GltfDocument gltf_twin(const scene::Model& model, const scene::Bundle& bundle) {
  const scene::Mesh& mesh = model.mesh;
  GltfDocument doc;
  std::map<std::string, int> image_of_path;
  const auto image_for = [&](int texture) {
    if (texture < 0) return -1;
    const std::string& path = model.textures[static_cast<std::size_t>(texture)].path;
    const auto [it, added] = image_of_path.try_emplace(path, static_cast<int>(doc.images.size()));
    if (added) doc.images.push_back({*bundle.find(path), media_type_of(path), path});
    return it->second;
  };
  for (const scene::Material& m : model.materials) {
    GltfMaterial material;
    material.base_colour = glm::vec4(m.diffuse, 1.0f);
    material.base_colour_image = image_for(m.diffuse_texture);
    material.normal_image = image_for(m.normal_texture);
    doc.materials.push_back(material);
  }
  GltfPrimitive all;
  all.positions = mesh.positions;
  all.normals = mesh.normals;
  for (const glm::vec2& t : mesh.texcoords) all.texcoords.emplace_back(t.x, 1.0f - t.y);
  for (const glm::vec3& c : mesh.colors)
    all.colours.emplace_back(srgb_decoded(c.r), srgb_decoded(c.g), srgb_decoded(c.b), 1.0f);
  std::vector<GltfPrimitive> primitives;
  for (const scene::Submesh& s : mesh.submeshes) {
    GltfPrimitive p = all;
    p.indices.assign(mesh.indices.begin() + s.first_index, mesh.indices.begin() + s.first_index + s.index_count);
    p.material = s.material;
    primitives.push_back(std::move(p));
  }
  doc.meshes.push_back(std::move(primitives));
  GltfNode node;
  node.mesh = 0;
  node.translation = mesh.origin;
  doc.nodes.push_back(node);
  doc.scene_roots = {0};
  return doc;
}

}  // namespace toond::test
