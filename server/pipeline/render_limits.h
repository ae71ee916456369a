#pragma once
// How much one render may draw; set from the daemon's --max-* flags.
#include <cstddef>
#include <cstdint>

namespace toond::pipeline {

struct RenderLimits {
  // width × height of the image answered.
  std::uint64_t max_output_pixels = 4096ull * 4096ull;
  // (width × supersample) × (height × supersample) × msaa. Each sample takes
  // 8 bytes (sRGB colour + depth/stencil), so the default keeps a render's
  // framebuffer near 1 GiB; the schema's extremes multiplied out (4096² ×
  // 16 × 8) would need 17 GiB.
  std::uint64_t max_samples = 4096ull * 4096ull * 8ull;
  std::size_t max_lights = 8;    // the schema's (and the shader's) most
  std::size_t max_objects = 16;  // the schema's most
  // The predicted cost of a request (render/plan/render_cost.h), in Msamples;
  // 0: no limit. The default is about 9 s of llvmpipe on 2 cores (under the
  // default --render-timeout) and 5× the dearest shared model at 4096²,
  // msaa 8, with any preset.
  double max_render_cost = 5000;
};

}  // namespace toond::pipeline
