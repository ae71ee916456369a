#pragma once
// The frames a request draws. A single image is one frame of the request's
// own parameters; a sheet's frames each show their view of the sheet's
// framing (render::frame_params), a pixel-art frame at its reduced size
// (render::pixel_art_frame_params). Priced, queued and assembled alike.
#include <vector>

#include "render/plan/render_params.h"

namespace toond::pipeline {

// The parameters each frame is drawn with, in layout order.
std::vector<render::RenderParams> drawn_frames(const render::RenderParams& params);

}  // namespace toond::pipeline
