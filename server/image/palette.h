#pragma once
// Exact palettes for images with few colours: toon frames are mostly flat
// bands, so many fit in 256 colours and can be written as 8-bit indices, a
// quarter of the RGBA bytes for the compressor to read. No quantisation: an
// image with one colour too many gets no palette at all.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "image/image.h"

namespace toond::image {

inline constexpr int kMaxPaletteColours = 256;

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

struct PalettedImage {
  // Colours with alpha below 255 come first, so a PNG tRNS chunk needs only
  // `translucent_count` entries.
  std::vector<Rgba8> colours;
  int translucent_count = 0;
  // One index per pixel, each row preceded by one spare byte, so the rows
  // are already laid out as PNG scanlines (the spare byte is the filter type,
  // left 0: no filter).
  std::vector<std::uint8_t> scanlines;
};

// The image as palette indices, or nullopt when it holds more than 256
// distinct RGBA values. Stops reading at the 257th colour.
std::optional<PalettedImage> make_palette(const Image& image);

}  // namespace toond::image
