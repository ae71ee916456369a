#include "sheet_files/tile_trim.h"

#include <algorithm>

namespace toond::sheet_files {

PixelRect visible_bounds(const image::Image& sheet, const PixelRect& tile) {
  int left = tile.x + tile.w;
  int right = tile.x - 1;
  int top = tile.y + tile.h;
  int bottom = tile.y - 1;
  for (int y = tile.y; y < tile.y + tile.h; ++y) {
    const std::uint8_t* row = sheet.pixel(tile.x, y);
    int first = -1;
    int last = -1;
    for (int x = 0; x < tile.w; ++x) {
      if (row[x * 4 + 3] == 0) continue;
      if (first < 0) first = x;
      last = x;
    }
    if (first < 0) continue;
    left = std::min(left, tile.x + first);
    right = std::max(right, tile.x + last);
    top = std::min(top, y);
    bottom = y;
  }
  if (right < left) return {tile.x, tile.y, 0, 0};
  return {left, top, right - left + 1, bottom - top + 1};
}

PixelRect visible_bounds(std::span<const image::Image* const> sheets, const PixelRect& tile) {
  PixelRect all{tile.x, tile.y, 0, 0};
  for (const image::Image* sheet : sheets) {
    const PixelRect one = visible_bounds(*sheet, tile);
    if (one.w == 0) continue;
    if (all.w == 0) {
      all = one;
      continue;
    }
    const int right = std::max(all.x + all.w, one.x + one.w);
    const int bottom = std::max(all.y + all.h, one.y + one.h);
    all.x = std::min(all.x, one.x);
    all.y = std::min(all.y, one.y);
    all.w = right - all.x;
    all.h = bottom - all.y;
  }
  return all;
}

}  // namespace toond::sheet_files
