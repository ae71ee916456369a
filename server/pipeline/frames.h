#pragma once
// The frames a request draws. A single image is one frame of the request's
// own parameters; a sheet's frames each show their view of the sheet's
// framing (render::frame_params), a pixel-art frame at its reduced size
// (render::pixel_art_frame_params). Priced, queued and assembled alike.
#include <optional>
#include <vector>

#include "render/plan/render_params.h"
#include "render/plan/sheet_layout.h"

namespace toond::pipeline {

// The sheet of `params` laid out (render/plan/sheet_layout.h); none for a
// single image. A request is laid out once, when it is resolved
// (resolve.h); the price's what-ifs (a smaller tile) lay out their own.
std::optional<render::SheetLayout> layout_of(const render::RenderParams& params);

// The parameters each frame is drawn with, in layout order: `layout` is
// layout_of(params).
std::vector<render::RenderParams> drawn_frames(const render::RenderParams& params,
                                               const std::optional<render::SheetLayout>& layout);

}  // namespace toond::pipeline
