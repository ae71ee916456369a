#pragma once
// A frame's surfaces as its line drawing sees them: every object's
// triangles at the level of detail the frame draws, in its pose, placed
// and turned into the camera's view space (the eye at the origin looking
// down -z), in double precision. Which way each triangle faces, and which
// may hide anything at all, is worked out once here.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/frame_plan.h"
#include "render/vector/mesh_edges.h"

namespace toond::render::vector {

// Which way a triangle turns: toward the eye (counter-clockwise on screen),
// away, or edge-on (or of no area), which is neither.
enum class Facing : std::int8_t { Away = -1, EdgeOn = 0, Toward = 1 };

struct ViewObject {
  std::uint32_t first_vertex = 0;  // its vertices in ViewMesh::points
  std::uint32_t first_triangle = 0;
  std::uint32_t triangle_count = 0;
  std::uint32_t group_offset = 0;  // its positions' ids in ViewMesh::groups
  std::size_t level = 0;           // the level of detail drawn
  const scene::Model* model = nullptr;
  const scene::SkinPose* pose = nullptr;
  std::shared_ptr<const ModelEdges> edges;
  glm::dmat4 to_view{1.0};  // the mesh's coordinates → view space
  // The side a closed object shows none of (its faces there lie behind
  // its others): those hide nothing, and lines between two of them are
  // hidden. Facing::EdgeOn: none.
  Facing hidden_side = Facing::EdgeOn;
};

struct ViewMesh {
  bool orthographic = false;
  std::vector<glm::dvec3> points;     // every object's vertices, view space
  std::vector<std::uint32_t> groups;  // per point: its welded position, numbered over every object
  std::uint32_t group_count = 0;
  std::vector<std::uint32_t> corners;  // three points a triangle, every object's drawn level
  std::vector<Facing> facing;          // per triangle
  std::vector<std::uint8_t> hides;     // per triangle: 1 where it may hide something
  // Per triangle, bit k: its side from corner k to the next borders another
  // triangle that hides (what both hide meets there, with no gap between).
  std::vector<std::uint8_t> shared_sides;
  std::vector<ViewObject> objects;
  // How far a point may stray from a surface and still count as on it: a
  // millionth of the scene's size (floats' rounding of the vertices is ten
  // times less).
  double tolerance = 0;

  std::size_t triangle_count() const { return corners.size() / 3; }
  glm::dvec3 corner(std::size_t triangle, int k) const { return points[corners[3 * triangle + k]]; }
};

// Which way the triangle (a, b, c), in view space, turns.
Facing facing_of(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, bool orthographic);

// The plan's objects (`objects`, in the plan's order; `models`: each one's
// model as shared, for the edge cache; poses posed on the CPU,
// scene::SkinPose::cpu_sums) at the levels of detail the plan chose.
ViewMesh view_mesh_of(const FramePlan& plan, std::span<const PlannedObject> objects,
                      std::span<const std::shared_ptr<const scene::Model>> models, EdgeCache& edges);

}  // namespace toond::render::vector
