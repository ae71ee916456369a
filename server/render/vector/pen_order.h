#pragma once
// The order a plotter's pen draws a layer's strokes in: from the page's
// corner, each next stroke the one that starts nearest to where the last
// ended (an open stroke may be drawn from either end, a closed one from
// any of its points), so that the pen travels little with the pen up.
#include <vector>

#include "render/vector/stroke_chains.h"

namespace toond::render::vector {

// Reorders `paths`, turning open ones end for end and starting closed
// ones at the point the pen meets them.
void order_for_pen(std::vector<Polyline>& paths);

// How far the pen travels up: from (0, 0) to the first stroke's start,
// then from each stroke's end (a closed one's start) to the next's start.
double pen_up_travel(const std::vector<Polyline>& paths);

}  // namespace toond::render::vector
