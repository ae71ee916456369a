#pragma once
// The sRGB transfer function, for the image steps that must work on
// linear light (averaging, un-premultiplying) over sRGB-encoded bytes.
#include <array>
#include <cstdint>

namespace toond::image {

// Linear value of each sRGB byte.
const std::array<float, 256>& srgb_to_linear_table();
// The nearest sRGB byte of a linear value (clamped to 0..1; NaN gives 0),
// from precomputed thresholds: the same byte as the formula, without a pow.
std::uint8_t linear_to_srgb_byte(float linear);

}  // namespace toond::image
