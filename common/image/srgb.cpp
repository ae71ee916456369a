#include "image/srgb.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace toond::image {
namespace {

// The defining formula: the byte nearest the encoded value.
std::uint8_t encode_by_formula(float linear) {
  const float c = linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// The formula costs a pow per channel, which made the supersampling
// downsample cost more than a GPU's whole frame. It is monotonic, so each
// byte b + 1 begins at one linear value, found once by bisecting the float
// bit patterns of 0..1 (ordered like their values); a pixel then costs a
// bucket lookup and a comparison or two, and gets the formula's byte.
constexpr int kBuckets = 4096;  // finer than the steepest part of the curve (~3295 bytes per unit)

struct Encoder {
  std::array<float, 255> rise{};               // rise[b]: the least linear value that encodes to b + 1
  std::array<std::uint8_t, kBuckets> first{};  // the byte at each bucket's low end

  Encoder() {
    for (int b = 0; b < 255; ++b) rise[static_cast<std::size_t>(b)] = least_encoding_to(b + 1);
    for (int k = 0; k < kBuckets; ++k) {
      const float low = static_cast<float>(k) / kBuckets;
      first[static_cast<std::size_t>(k)] =
          static_cast<std::uint8_t>(std::upper_bound(rise.begin(), rise.end(), low) - rise.begin());
    }
  }

  static float least_encoding_to(int byte) {
    std::uint32_t lo = 0, hi = std::bit_cast<std::uint32_t>(1.0f);  // encodes below at lo, to byte at hi
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      (encode_by_formula(std::bit_cast<float>(mid)) >= byte ? hi : lo) = mid;
    }
    return std::bit_cast<float>(hi);
  }

  std::uint8_t operator()(float linear) const {
    if (!(linear > 0.0f)) return 0;  // NaN too
    if (linear >= 1.0f) return 255;
    int b = first[static_cast<std::size_t>(linear * kBuckets)];
    while (b < 255 && linear >= rise[static_cast<std::size_t>(b)]) ++b;
    return static_cast<std::uint8_t>(b);
  }
};

}  // namespace

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const float c = static_cast<float>(i) / 255.0f;
      t[static_cast<std::size_t>(i)] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    }
    return t;
  }();
  return table;
}

std::uint8_t linear_to_srgb_byte(float linear) {
  static const Encoder encode;
  return encode(linear);
}

}  // namespace toond::image
