#pragma once
// A tile cut to its pixels: the smallest rectangle that holds every pixel
// that is not fully transparent. A fully transparent pixel's colour shows
// nowhere, so it is trimmed whatever its colour.
#include <span>

#include "image/image.h"
#include "sheet_files/atlas_view.h"

namespace toond::sheet_files {

// The bounds of `tile` (a rectangle of `sheet`) that hold its visible
// pixels, in the sheet's coordinates; w = h = 0 when it has none.
PixelRect visible_bounds(const image::Image& sheet, const PixelRect& tile);

// The same over several sheets laid out alike (a sheet's layers): the
// smallest rectangle that holds every visible pixel of any of them.
PixelRect visible_bounds(std::span<const image::Image* const> sheets, const PixelRect& tile);

}  // namespace toond::sheet_files
