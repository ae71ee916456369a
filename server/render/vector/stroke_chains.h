#pragma once
// Strokes: the visible (or hidden) pieces of one layer joined end to end
// through the points they share into the longest polylines, each piece in
// exactly one. A walk starts at an end that cannot be passed through (a
// point where an odd number of pieces meet), so as few strokes as possible
// start and stop; at a point where several go on it takes the straightest;
// what is left after every such walk are loops, drawn as closed paths.
// Pieces join only where they share a mesh vertex or a seam's point, never
// where a line is cut by what hides it.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace toond::render::vector {

// A piece ready to chain: its ends on screen and the points it joins at
// (equal ids join; an end that joins nothing has an id of its own).
struct StrokePiece {
  std::uint32_t node0 = 0, node1 = 0;
  glm::dvec2 p0{0.0}, p1{0.0};
};

struct Polyline {
  std::vector<glm::dvec2> points;
  bool closed = false;  // the last point joins the first (not repeated)
};

// `node_count`: every id is below it.
std::vector<Polyline> chain_strokes(const std::vector<StrokePiece>& pieces, std::uint32_t node_count);

// Open strokes whose ends lie within `gap` pixels of each other joined into
// one (an end that comes back to its own start closes it): where a line
// passes behind another, the visible pieces on either side meet at the
// occluding line only to within the stroke's width, and a pen need not
// lift for that.
std::vector<Polyline> stitch_strokes(std::vector<Polyline> strokes, double gap);

}  // namespace toond::render::vector
