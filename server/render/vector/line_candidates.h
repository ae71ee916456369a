#pragma once
// The segments a frame's line drawing may draw, before visibility: every
// edge where a face turned toward the eye meets one turned away
// (silhouettes), every open edge (boundaries), the crease edges creased at
// the request's angle whose two faces turn alike (a crease edge whose faces
// turn apart is a silhouette), and the seams where parts cross that turn as
// far (scene/mesh/intersection_lines.h), in the objects' poses.
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "render/vector/line_kind.h"
#include "render/vector/view_mesh.h"

namespace toond::render::vector {

inline constexpr std::uint32_t kNoGroup = std::numeric_limits<std::uint32_t>::max();
inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

struct Segment {
  glm::dvec3 a{0.0}, b{0.0};  // view space
  // Where it joins other segments: its ends' welded positions (ViewMesh::
  // groups), or for a seam the points it shares with its neighbours.
  std::uint32_t node_a = 0, node_b = 0;
  // The welded positions of its ends, for a mesh edge: the faces holding
  // both border it and hide none of it. kNoGroup for a seam.
  std::uint32_t group_a = kNoGroup, group_b = kNoGroup;
  LineKind kind = LineKind::Silhouette;
  // A silhouette's or open edge's side where its surface lies: a corner of
  // the face beside it that turns toward the eye (its only face, for an
  // open edge), view space. The other side shows what lies behind it.
  glm::dvec3 surface_side{0.0};
  // That face (a triangle of the ViewMesh), whose colour the line may
  // take; kNoTriangle for a crease or a seam.
  std::uint32_t face = kNoTriangle;
  // Between two faces of a closed object's hidden side: hidden whole.
  bool surely_hidden = false;
};

// Which silhouettes and open edges are drawn where they show: those the
// request's outline methods draw.
enum class ContourRule {
  Outline,    // the outline alone: nothing beside it on its far side (the hull's ring)
  DepthJump,  // and where what lies beside it is farther by the depth threshold (the edge pass)
  All,        // every one that shows (back-face wireframe, contour lines)
};

// Which kinds of line the drawing holds (those the request's PNG draws).
struct LineChoice {
  ContourRule contours = ContourRule::Outline;
  double depth_jump = 0;  // DepthJump: in view-space units
  bool silhouettes = false;
  bool boundaries = false;
  bool creases = false;
  bool intersections = false;
  double crease_angle_deg = 40;
  // Lines hidden whole are kept too (for a hidden layer); otherwise those
  // surely hidden are left out.
  bool keep_hidden = false;
};

struct Candidates {
  std::vector<Segment> segments;
  std::uint32_t node_count = 0;  // nodes are numbered below this
};

Candidates line_candidates(const ViewMesh& mesh, const LineChoice& choice);

}  // namespace toond::render::vector
