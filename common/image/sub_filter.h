#pragma once
// PNG scanlines for truecolour images: each row behind its filter-type byte
// (1, Sub), every byte minus the same channel of the pixel to its left. On a
// toon frame that turns each flat band into a run of zeros that run-length
// deflate swallows whole; it is also the cheapest filter to compute.
#include <cstdint>
#include <span>
#include <vector>

#include "image/image.h"

namespace toond::image {

enum class TruecolourLayout { Rgb, Rgba };

inline int bytes_per_pixel(TruecolourLayout layout) { return layout == TruecolourLayout::Rgb ? 3 : 4; }

// The Sub-filtered scanlines of rows [first_row, first_row + row_count),
// written into `scratch` (resized to fit); Rgb drops the alpha channel.
std::span<const std::uint8_t> sub_filtered_rows(const Image& image, TruecolourLayout layout, int first_row,
                                                int row_count, std::vector<std::uint8_t>& scratch);

// True when every pixel has alpha 255, so RGB loses nothing; checked in
// `parts` bands of pixels on up to `threads` threads
// (image/parallel_tasks.h). The encoder cuts it like its deflate strips.
bool is_opaque(const Image& image, int parts = 1, int threads = 1);

}  // namespace toond::image
