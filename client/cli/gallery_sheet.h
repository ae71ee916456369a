#pragma once
// The contact sheet of `toon gallery`: every render as a thumbnail on one
// image, rows = models, columns = looks.
#include <vector>

#include "image/image.h"

namespace toond::cli::gallery {

// Thumbnails are at most this many pixels on a side.
inline constexpr int kMaxThumbnail = 128;
// Pixels between thumbnails and around the sheet's border.
inline constexpr int kSheetGap = 2;

// The smallest integer factor that brings `size` down to kMaxThumbnail or less.
int thumbnail_factor(int size);

// `source` shrunk by an integer box filter (averaged in linear light, see
// image::downsample_box). Rows and columns that do not fill a whole block
// (size not a multiple of `factor`) are dropped from the right and bottom.
image::Image make_thumbnail(const image::Image& source, int factor);

// Cells of `cell_width` × `cell_height` in a grid with `gap` pixels between
// them and around the border, on an opaque dark grey. `rows[r][c]` is drawn
// centred in cell (r, c), clipped to it; a null entry (a failed render) is
// filled with dark red. The sheet is
//   columns × cell_width + (columns + 1) × gap  wide and
//   rows × cell_height + (rows + 1) × gap  high,
// where `columns` is the longest row.
image::Image assemble_contact_sheet(const std::vector<std::vector<const image::Image*>>& rows, int cell_width,
                                    int cell_height, int gap = kSheetGap);

// The colours assemble_contact_sheet uses (RGBA), exposed for tests.
inline constexpr unsigned char kSheetBackground[4] = {44, 44, 48, 255};
inline constexpr unsigned char kSheetMissing[4] = {150, 30, 36, 255};

}  // namespace toond::cli::gallery
