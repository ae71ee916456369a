#pragma once
// What the schema cannot say about a `sheet` on its own because it ties
// fields together: checked once the request is parsed, before anything is
// laid out or rendered.
#include "render/plan/render_params.h"

namespace toond::pipeline {

// Throws RequestError (400 invalid_parameter) when pixel art's scale does
// not divide width and height (at /sheet/pixel_art/scale: a tile must be
// whole art pixels, or the blocks would not line up with the tile), or when
// pixel art, animate or pack is asked of a data layer (output depth,
// normal or id; at /sheet/pixel_art, /sheet/animate or /sheet/pack), or
// pack of an animated WebP (at /sheet/pack), or when sheet.layers is given
// with an output that is not among them or is not color or lines (at
// /sheet/layers).
void check_sheet_params(const render::RenderParams& params);

}  // namespace toond::pipeline
