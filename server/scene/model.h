#pragma once
// The in-memory form of an imported model: what the importer produces and
// what the GPU upload consumes. Plain data, no GL.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace toond::scene {

// A decoded image, RGBA8, rows top to bottom, colour values sRGB-encoded
// (alpha linear), as read from the bundle.
struct Texture {
  std::string path;  // path inside the bundle it came from
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

struct Material {
  std::string name;
  glm::vec3 diffuse{0.8f};     // Kd, linear (MTL values are taken as linear)
  int diffuse_texture = -1;    // index into Model::textures, -1 = none
};

// A run of triangles drawn with one material.
struct Submesh {
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  int material = 0;  // index into Model::materials
};

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  glm::vec3 centre() const { return (min + max) * 0.5f; }
  // Radius of the sphere around centre() that holds the box.
  float radius() const { return glm::length(max - min) * 0.5f; }
};

// Triangle mesh with one vertex stream. Positions are stored relative to
// `origin` (computed in double precision) so that geometry far from the
// model's own origin keeps full float precision on the GPU.
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;          // unit length, shading normals
  std::vector<glm::vec3> outline_normals;  // hull offset per unit width: shared by
                                           // every vertex at a position (no gaps at
                                           // hard edges), mitred at corners (see
                                           // compute_outline_normals)
  std::vector<glm::vec2> texcoords;        // (0,0) where the OBJ had none
  std::vector<std::uint32_t> indices;      // triangles
  std::vector<Submesh> submeshes;
  glm::dvec3 origin{0.0};  // model-space point that positions are relative to
  Bounds bounds;           // of `positions` (i.e. relative to origin)

  std::size_t triangle_count() const { return indices.size() / 3; }
};

struct Model {
  Mesh mesh;
  std::vector<Material> materials;  // never empty after import
  std::vector<Texture> textures;
  std::vector<std::string> warnings;
};

}  // namespace toond::scene
