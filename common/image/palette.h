#pragma once
// Exact palettes for images with few colours: toon frames are mostly flat
// bands, so many fit in 256 colours and can be written as 8-bit indices, a
// quarter of the RGBA bytes for the compressor to read. No quantisation: an
// image with one colour too many gets no palette at all.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "image/colour_table.h"
#include "image/image.h"

namespace toond::image {

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

class Palette {
 public:
  // In index order; colours with alpha below 255 come first, so a PNG tRNS
  // chunk needs only translucent_count() entries.
  const std::vector<Rgba8>& colours() const { return colours_; }
  int translucent_count() const { return translucent_count_; }

  // Rows [first_row, first_row + row_count) of `image` (the image the
  // palette was found for) as PNG scanlines, written into `scratch`: a filter
  // byte of 0 (none), then one index per pixel.
  std::span<const std::uint8_t> index_rows(const Image& image, int first_row, int row_count,
                                           std::vector<std::uint8_t>& scratch) const;

 private:
  friend std::optional<Palette> find_palette(const Image& image, int threads);
  std::vector<Rgba8> colours_;
  int translucent_count_ = 0;
  ColourTable lookup_;  // colour -> index in colours_
};

// The palette of an image holding at most 256 distinct RGBA values, or
// nullopt; stops reading at the 257th colour. With `threads` above 1,
// horizontal bands are scanned at once (run_tasks), each with its own table,
// and their colours merged.
std::optional<Palette> find_palette(const Image& image, int threads = 1);

}  // namespace toond::image
