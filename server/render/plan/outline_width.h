#pragma once
// Every outline method (hull, wireframe, screen-space edges) draws the
// width the request asks for, converted here once: a `px` width is taken
// as it is; a `world` width becomes pixels at the depth of the point the
// camera looks at (the model's centre), so the whole outline is one width,
// as a pixel width is, whichever method draws it.
#include "render/plan/camera.h"
#include "render/plan/render_params.h"

namespace toond::render {

// The widest outline any method draws, in output pixels: the schema's
// limit for `px` widths, which `world` widths meet after conversion too.
inline constexpr double kMaxOutlinePx = 64.0;

// The outline's width in output pixels (before supersampling).
double outline_width_px(const OutlineParams& outline, const CameraSetup& camera, bool orthographic, int output_height);

}  // namespace toond::render
