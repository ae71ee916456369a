#pragma once
// What the schema cannot say about a `sheet` on its own because it ties
// fields together: checked once the request is parsed, before anything is
// laid out or rendered.
#include "render/render_params.h"

namespace toond::http {

// Throws RequestError (400 invalid_parameter at /sheet/pixel_art/scale)
// when pixel art's scale does not divide width and height: a tile must be
// whole art pixels, or the blocks would not line up with the tile.
void check_sheet_params(const render::RenderParams& params);

}  // namespace toond::http
