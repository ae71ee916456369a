#pragma once
// Which silhouettes and open edges a request's outline draws where they
// show (LineChoice::contours): the hull's ring only the outline, where
// nothing lies just beyond the line on its far side (a surface there would
// cover the ring); the edge pass also where what lies there is farther by
// its depth threshold; the back-face wireframe and contour lines every
// one. A dense scan's surface folds over itself in many small places seen
// nearly edge-on, each a silhouette of a pixel or two over the same
// surface: the outline methods draw none of them, and neither does this.
#include <vector>

#include "render/vector/line_candidates.h"
#include "render/vector/occluder_grid.h"
#include "render/vector/screen_map.h"
#include "render/vector/segment_visibility.h"

namespace toond::render::vector {

// `pieces` with the visible pieces of silhouettes and open edges cut to the
// stretches the rule keeps, judged every pixel or so along them, `reach_px`
// beyond the line; every other piece as it was.
std::vector<Piece> keep_drawn_contours(const std::vector<Piece>& pieces, const std::vector<Segment>& segments,
                                       const OccluderGrid& grid, const ScreenMap& screen, const LineChoice& choice,
                                       double reach_px);

}  // namespace toond::render::vector
