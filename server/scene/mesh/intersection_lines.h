#pragma once
// Intersection lines: where separate parts of a model pass through each
// other (an eye pushed into a head, a sphere sunk into the box it sits
// on), the seam between the two surfaces shows as a line, as a crease
// does, though no edge of either runs along it. Import finds those seams
// as segments, one where a triangle of one part crosses a triangle of
// another, and the crease pass draws them beside the crease edges
// (render/passes/crease_pass.cpp), sorted the same way by how far the
// surface turns across them.
//
// Parts are the connected pieces of the mesh (triangles sharing a point;
// split copies of a vertex count as one). Triangles of one part are not
// compared: a part passing through itself draws no line here.
//
// Two triangles cross (their corners read in double, to a tolerance of a
// millionth of the bounding box's diagonal) where their planes are not
// parallel, each reaches the other's plane, and both hold a stretch of
// the line where the planes meet longer than the tolerance. Triangles
// lying in one plane meet in an area, not along a line: none. Triangles
// that touch the line only with an edge each (boxes stacked flush, whose
// sides continue one another) meet at their rims, where no fold shows:
// none either; a triangle whose edge lies inside the other's face (a
// block standing on a floor, an ear set on a head) does make one.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/crease_edges.h"

namespace toond::scene {

struct Mesh;

struct IntersectionLines : TurnTally {
  // Four points a segment, for GL_LINES_ADJACENCY: p1, a, b, p2. a and b
  // are its ends; p1 lies in the plane of the first triangle and p2 in the
  // second's, off the line on the side that makes (a, b, p1) wind as the
  // first triangle does and (a, b, p2) as the second: whether each faces
  // the eye is the view's to tell, and so is which half of each plane
  // shows (shaders/crease.geom).
  std::vector<glm::vec3> points;
  // false: the search gave up (parts crowding through one another's
  // boxes, more to compare or to keep than IntersectionSearch allows, or
  // its deadline passed), and kept none of what it found:
  // the pass plan has the frames of this model find their lines in screen
  // space (render/plan/intersections_known.h).
  bool complete = true;

  std::size_t size() const { return points.size() / 4; }
};

struct IntersectionSearch {
  // Pairs of boxes and of triangles compared, a triangle, before the
  // search gives up (a mesh of few triangles may always compare
  // kLeastIntersectionWork): a model of well-apart parts compares a few a
  // triangle, parts crowding through one another (hair cards, a stack of
  // copies) many more. It bounds the search's time by the mesh's size,
  // the same on every machine.
  double work_per_triangle = 64;
  // Nor does it keep more segments than this a triangle (a mesh of few
  // triangles may always keep kLeastIntersectionSegments): parts crossing
  // one another that often (a field of grass cards) have their lines
  // found in screen space. The shared windmill, of 138 parts, has 1.1.
  double segments_per_triangle = 4;
  // Nor does it go on past this (the import's deadline): it gives up
  // rather than abandon the import.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

inline constexpr std::size_t kLeastIntersectionWork = 65536;
inline constexpr std::size_t kLeastIntersectionSegments = 1024;

// Each vertex's connected part, numbered from 0 in the order triangles
// first reach them; `parts` gets how many there are. A vertex no triangle
// uses gets none (UINT32_MAX).
std::vector<std::uint32_t> label_parts(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                       std::uint32_t& parts);

// The segments where triangles of different parts (`part_of_vertex`, from
// label_parts) cross, those that turn by more than 1° (between the two
// surfaces' shading normals at the segment's ends, the larger, as crease
// edges turn), greatest turn first. Degenerate triangles cross nothing.
IntersectionLines find_intersection_lines(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                          std::span<const std::uint32_t> indices,
                                          std::span<const std::uint32_t> part_of_vertex,
                                          const IntersectionSearch& search = {});

// The segments where the parts of `mesh` cross with its vertices at
// `positions` (shaded by `normals`): a pose of it, whose topology, parts
// and levels of detail are the rest mesh's. One IntersectionLines a level,
// the full mesh first, each with a budget of its own; all empty for a mesh
// of one part; where the full mesh's search gives up, the levels' are
// given up unseen.
std::vector<IntersectionLines> find_intersection_lines(const Mesh& mesh, std::span<const glm::vec3> positions,
                                                       std::span<const glm::vec3> normals,
                                                       const IntersectionSearch& search = {});

// Sets Mesh::parts, and Mesh::intersections for the full mesh and every
// level of detail (a level's own triangles cross where they do), each
// level with a budget of its own. A mesh of one part searches nothing;
// where the full mesh's search gives up, the levels' are given up unseen.
void find_intersection_lines(Mesh& mesh, const IntersectionSearch& search = {});

}  // namespace toond::scene
