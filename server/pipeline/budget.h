#pragma once
// Admission of a render request's size against the daemon's --max-*
// limits, before anything is posed or priced; its errors name the flags.
#include <optional>

#include "pipeline/render_limits.h"
#include "render/plan/render_params.h"
#include "render/plan/sheet_layout.h"

namespace toond::pipeline {

using render::RenderParams;

// The largest framebuffer side GL is asked for, whatever the limits say.
inline constexpr int kMaxDrawnSide = 16384;

// Throws LimitError (422, "limit_exceeded", naming the flag and the parameter
// to lower) when a render would exceed the output pixels, the sample budget
// (width × supersample × height × supersample × msaa), the largest
// framebuffer side, or the lights or objects allowed. A sheet's whole image
// and all its frames' samples count too, once per layer of sheet.layers
// (the answers that draw them all hold them at once): `layout` is the sheet's
// (frames.h: layout_of), none for a single image.
void check_render_budget(const RenderParams& params, const std::optional<render::SheetLayout>& layout,
                         const RenderLimits& limits = {});

}  // namespace toond::pipeline
