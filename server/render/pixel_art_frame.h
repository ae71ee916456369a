#pragma once
// How a pixel-art sheet's tile is drawn (`sheet.pixel_art`): small, and
// with nothing that blends colours, so every art pixel is one colour of
// the scene that the shared palette then snaps.
#include "render/render_params.h"

namespace toond::render {

// `frame` (one frame's parameters, as frame_params gives them) drawn at
// 1/scale of its size, one sample a pixel, band edges hard. `scale` divides
// width and height (the HTTP layer checks).
RenderParams pixel_art_frame_params(RenderParams frame, int scale);

}  // namespace toond::render
