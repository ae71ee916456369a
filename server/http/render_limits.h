#pragma once
// How much one render may draw; set from the daemon's --max-* flags.
#include <cstddef>
#include <cstdint>

namespace toond::http {

struct RenderLimits {
  // width × height of the image answered.
  std::uint64_t max_output_pixels = 4096ull * 4096ull;
  // (width × supersample) × (height × supersample) × msaa. Each sample takes
  // 8 bytes (sRGB colour + depth/stencil), so the default keeps a render's
  // framebuffer near 1 GiB; the schema's extremes multiplied out (4096² ×
  // 16 × 8) would need 17 GiB.
  std::uint64_t max_samples = 4096ull * 4096ull * 8ull;
  std::size_t max_lights = 8;   // the schema's (and the shader's) most
  std::size_t max_objects = 16;  // the schema's most
};

}  // namespace toond::http
