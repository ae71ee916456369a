#pragma once
#include "render/render_limits.h"
#include "render/render_params.h"

namespace toond::render {

// The largest framebuffer side GL is asked for, whatever the limits say.
inline constexpr int kMaxDrawnSide = 16384;

// Throws LimitError (422, "limit_exceeded", naming the flag and the parameter
// to lower) when a render would exceed the output pixels, the sample budget
// (width × supersample × height × supersample × msaa), the largest
// framebuffer side, or the lights or objects allowed. A sheet's whole image
// and all its frames' samples count too.
void check_render_budget(const RenderParams& params, const RenderLimits& limits = {});

}  // namespace toond::render
