#pragma once
// The in-memory form of an imported model: what the importer produces and
// what the GPU upload consumes. Plain data, no GL.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/crease_edges.h"
#include "scene/mesh/crease_profile.h"
#include "scene/mesh/intersection_lines.h"
#include "scene/mesh/render_cost_profile.h"
#include "scene/mesh/rig.h"

namespace toond::scene {

// How a texture's RGB bytes are to be read (alpha is always linear).
enum class ColorSpace {
  Srgb,    // colour maps (map_Kd): sRGB-encoded, to be decoded when sampled
  Linear,  // data maps (normal maps): the bytes are the values
};

// A decoded image, RGBA8, rows top to bottom, as read from the bundle. A file
// that serves both as a colour map and as a normal map is stored twice, once
// per colour space, so each copy can be uploaded with its own GL format.
struct Texture {
  std::string path;  // path inside the bundle it came from
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
  ColorSpace color_space = ColorSpace::Srgb;
  // The least alpha of any texel (255: opaque), so a mask that would cut
  // nothing costs nothing (texture_alpha.h).
  std::uint8_t min_alpha = 255;
};

// How a material's alpha (opacity × its colour texture's alpha) is drawn:
// ignored, as a cut-out (below the cutoff nothing is drawn: leaves, fences,
// a hat layer's empty texels) or blended over what lies behind.
enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

// How a texture is sampled, as the file says (glTF samplers); Unspecified
// leaves it to the request (`textures.filter`, auto: nearest magnification
// for small textures, as pixel-art games draw them).
enum class TextureFilter : std::uint8_t { Unspecified, Nearest, Linear };
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge, MirroredRepeat };
struct Sampler {
  TextureFilter magnification = TextureFilter::Unspecified;
  // Minification: Nearest picks texels without blending between them (glTF
  // NEAREST and NEAREST_MIPMAP_*), Linear blends; mipmaps as the request
  // draws them either way.
  TextureFilter minification = TextureFilter::Unspecified;
  TextureWrap wrap_s = TextureWrap::Repeat;
  TextureWrap wrap_t = TextureWrap::Repeat;
  bool operator==(const Sampler&) const = default;
};

struct Material {
  std::string name;
  glm::vec3 diffuse{0.8f};   // Kd, linear (MTL values are taken as linear)
  int diffuse_texture = -1;  // index into Model::textures, -1 = none
  // Tangent-space normal map (MTL map_Bump / bump / norm; Blender writes its
  // normal maps as map_Bump), index into Model::textures, -1 = none. Always
  // a ColorSpace::Linear texture. Convention: OpenGL / Blender, i.e. RGB =
  // (n * 0.5 + 0.5) in the basis (Mesh::tangents.xyz, bitangent, normal),
  // green along +V of the texture coordinates (V up, as OBJ has it).
  int normal_texture = -1;
  // Ks, linear, clamped to 0..1; 0 when the MTL gives none. Caution: the
  // nvdiffrec MTLs (spot, bob) write "Ks 0 <roughness> <metalness>", e.g.
  // "Ks 0 0.25 0"; kept as written, so a Phong reading of it is a faint
  // green highlight.
  glm::vec3 specular{0.0f};
  // Ns, the Phong exponent, clamped to 0..1000 (the MTL range); 32 when the
  // MTL gives none. Blender writes 0 for fully rough materials.
  float shininess = 32.0f;
  // The base colour's alpha (glTF baseColorFactor.a; MTL d, 1 - Tr).
  float opacity = 1.0f;
  // What the alpha means (glTF alphaMode; MTL d, Tr, map_d and the alpha
  // of map_Kd; the format's engine's convention where the file says
  // nothing: docs/formats.md, "Game files").
  AlphaMode alpha_mode = AlphaMode::Opaque;
  // Mask: a fragment whose alpha (opacity × the base colour texture's
  // alpha) is below this is not drawn (glTF alphaCutoff, 0.5 by default).
  float alpha_cutoff = 0.5f;
  // glTF KHR_materials_unlit: the base colour as it is, no bands or light.
  bool unlit = false;
  // The file says the surface has no highlight (MTL Ks 0 0 0 or illum 0
  // or 1, glTF fully rough without a specular extension, a converted
  // file's zero specular): `specular.source: material` draws no spot on it.
  bool matte = false;
  // How the colour texture is sampled, where the file says (glTF).
  Sampler sampler;
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
  // Corner i (0..7) of the box: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
  glm::dvec3 corner(int i) const { return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z}; }
};

// Whether triangles close around a volume (scene/mesh/enclosure.h), once the
// holes in them are capped. Closed: every edge (between positions, split
// copies of a vertex counting as one) is crossed as often in one direction
// as in the other, so the triangles bound a volume. Outward:
// counter-clockwise faces look out of it, as OBJ exporters write them;
// Inward: the whole mesh is wound inside out. Open covers inconsistent
// winding, edges three or more faces share unevenly, holes whose rims touch
// themselves, flat or zero-volume parts (a two-sided sheet), and meshes
// whose parts disagree in direction (a hollow shell with an inward-facing
// cavity): anything where a face turned away from the camera might be the
// one that shows from any side.
enum class Enclosure : std::uint8_t { Open, Outward, Inward };

// A coarser level of detail over the same vertices as its Mesh (see
// scene/mesh/mesh_lod.h).
struct MeshLod {
  std::vector<std::uint32_t> indices;  // triangles
  std::vector<Submesh> submeshes;      // ranges of `indices`, one per Mesh::submeshes entry, same materials
  double error = 0;                    // how far the surface may stray from the full mesh, mesh units
  Enclosure enclosure = Enclosure::Open;
  std::vector<glm::vec3> caps;             // see Mesh::caps
  std::vector<std::uint32_t> cap_indices;  // see Mesh::cap_indices
  CreaseEdges crease_edges;                // see Mesh::crease_edges
  IntersectionLines intersections;         // see Mesh::intersections

  std::size_t triangle_count() const { return indices.size() / 3; }
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
  std::vector<glm::vec2> texcoords;        // (0,0) where the file had none
  // Per vertex, for normal maps: xyz is a unit tangent orthogonal to the
  // shading normal, pointing along +U of the texcoords; w = +1 or -1 is the
  // handedness, bitangent = w * cross(normal, tangent.xyz) (points along +V).
  // Where the UVs are missing or degenerate: some unit vector perpendicular
  // to the normal, w = +1. Never NaN.
  std::vector<glm::vec4> tangents;
  // Vertex colours as the file gives them (OBJ "v x y z r g b", .m
  // rgb=(r g b)), 0..1 and NOT linearised: like colour-picker values they
  // are sRGB-encoded, to be decoded where they are used. Either empty (the
  // file has none) or one per position.
  std::vector<glm::vec3> colors;
  // Per vertex, how it moves (an index into Rig::motions) when its model
  // has a rig; empty when not.
  std::vector<std::uint32_t> motion;
  std::vector<std::uint32_t> indices;  // triangles
  std::vector<Submesh> submeshes;
  std::vector<MeshLod> lods;              // coarser levels, finest first; empty: full detail only
  Enclosure enclosure = Enclosure::Open;  // of `indices`, the full mesh
  // Triangles (three points each) that close the holes of an Outward or
  // Inward mesh, wound like it; empty when it has none. Through a hole one
  // sees the inner faces: they can only be skipped while every cap is
  // turned away from the camera.
  std::vector<glm::vec3> caps;
  // The same triangles as indices of `positions` (a vertex at each rim
  // point), so a render can draw them with the mesh's own vertices: through
  // the outline hull's offset too.
  std::vector<std::uint32_t> cap_indices;
  // Positions this close were welded into one (scene/mesh/position_weld.h), and
  // how many were moved to do so: the import report shows both.
  double weld_tolerance = 0;
  std::size_t welded_positions = 0;
  // How much of the edge length is creased at each angle (scene/mesh/crease_profile.h).
  CreaseProfile creases;
  // The edges that turn, greatest turn first, that crease lines are drawn
  // along (scene/mesh/crease_edges.h).
  CreaseEdges crease_edges;
  // How many connected parts the triangles make, and the segments where
  // those of different parts cross, greatest turn first, that intersection
  // lines are drawn along (scene/mesh/intersection_lines.h).
  std::uint32_t parts = 1;
  IntersectionLines intersections;
  // What rasterising the full mesh once costs (scene/mesh/render_cost_profile.h):
  // what a request is priced by before it is queued.
  RenderCostProfile cost;
  // Vertices extreme along many directions (scene/mesh/extreme_points.h): what
  // the camera projects to frame the model tightly.
  std::vector<glm::vec3> extremes;
  glm::dvec3 origin{0.0};  // model-space point that positions are relative to
  Bounds bounds;           // of `positions` (i.e. relative to origin)

  std::size_t triangle_count() const { return indices.size() / 3; }
};

struct Model {
  Mesh mesh;
  std::vector<Material> materials;  // never empty after import
  std::vector<Texture> textures;
  bool has_vertex_colors = false;  // == !mesh.colors.empty()
  std::vector<std::string> warnings;
  // Skins, morph targets and clips (scene/mesh/rig.h); null when nothing moves.
  // Shared: it is read-only once imported.
  std::shared_ptr<const Rig> rig;
};

}  // namespace toond::scene
