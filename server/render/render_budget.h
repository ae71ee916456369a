#pragma once
#include "render/render_params.h"

namespace toond::render {

// The most samples one render may draw: (width × supersample) ×
// (height × supersample) × msaa. Each sample takes 8 bytes (sRGB colour +
// depth/stencil), so this keeps a render's framebuffer near 1 GiB; the
// schema's extremes multiplied out (4096² × 16 × 8) would need 17 GiB.
inline constexpr double kMaxDrawnSamples = 4096.0 * 4096.0 * 8.0;
inline constexpr int kMaxDrawnSide = 16384;

// Throws RequestError (422) naming the parameter to lower when a render would
// exceed the sample budget or the largest framebuffer side.
void check_render_budget(const RenderParams& params);

}  // namespace toond::render
