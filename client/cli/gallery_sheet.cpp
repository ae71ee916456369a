#include "gallery_sheet.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "image/downsample.h"

namespace toond::cli::gallery {
namespace {

void fill(image::Image& img, int x0, int y0, int w, int h, const unsigned char (&rgba)[4]) {
  for (int y = std::max(0, y0); y < std::min(img.height, y0 + h); ++y) {
    for (int x = std::max(0, x0); x < std::min(img.width, x0 + w); ++x) {
      std::memcpy(img.pixel(x, y), rgba, 4);
    }
  }
}

}  // namespace

int thumbnail_factor(int size) {
  if (size <= kMaxThumbnail) return 1;
  return (size + kMaxThumbnail - 1) / kMaxThumbnail;
}

image::Image make_thumbnail(const image::Image& source, int factor) {
  if (factor < 1) throw std::invalid_argument("make_thumbnail: factor must be at least 1");
  const int w = source.width / factor * factor;
  const int h = source.height / factor * factor;
  if (w == 0 || h == 0) throw std::invalid_argument("make_thumbnail: image smaller than the factor");
  if (w == source.width && h == source.height) return image::downsample_box(source, factor);
  image::Image cropped;
  cropped.width = w;
  cropped.height = h;
  cropped.rgba.resize(static_cast<std::size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    std::memcpy(cropped.pixel(0, y), source.pixel(0, y), static_cast<std::size_t>(w) * 4);
  }
  return image::downsample_box(cropped, factor);
}

image::Image assemble_contact_sheet(const std::vector<std::vector<const image::Image*>>& rows, int cell_width,
                                    int cell_height, int gap) {
  if (cell_width < 1 || cell_height < 1 || gap < 0) {
    throw std::invalid_argument("assemble_contact_sheet: bad cell size or gap");
  }
  std::size_t columns = 0;
  for (const auto& row : rows) columns = std::max(columns, row.size());
  const int ncols = static_cast<int>(columns);
  const int nrows = static_cast<int>(rows.size());

  image::Image sheet;
  sheet.width = std::max(1, ncols * cell_width + (ncols + 1) * gap);
  sheet.height = std::max(1, nrows * cell_height + (nrows + 1) * gap);
  sheet.rgba.resize(static_cast<std::size_t>(sheet.width) * sheet.height * 4);
  fill(sheet, 0, 0, sheet.width, sheet.height, kSheetBackground);

  for (int r = 0; r < nrows; ++r) {
    const auto& row = rows[static_cast<std::size_t>(r)];
    for (int c = 0; c < static_cast<int>(row.size()); ++c) {
      const int cx = gap + c * (cell_width + gap);
      const int cy = gap + r * (cell_height + gap);
      const image::Image* img = row[static_cast<std::size_t>(c)];
      if (!img) {
        fill(sheet, cx, cy, cell_width, cell_height, kSheetMissing);
        continue;
      }
      // Centred; whatever overhangs the cell is clipped.
      const int ox = cx + (cell_width - img->width) / 2;
      const int oy = cy + (cell_height - img->height) / 2;
      for (int y = 0; y < img->height; ++y) {
        const int sy = oy + y;
        if (sy < cy || sy >= cy + cell_height) continue;
        for (int x = 0; x < img->width; ++x) {
          const int sx = ox + x;
          if (sx < cx || sx >= cx + cell_width) continue;
          // Transparent render backgrounds are composited over the sheet's grey.
          const std::uint8_t* p = img->pixel(x, y);
          std::uint8_t* q = sheet.pixel(sx, sy);
          const unsigned a = p[3];
          for (int k = 0; k < 3; ++k) {
            q[k] = static_cast<std::uint8_t>((p[k] * a + q[k] * (255u - a) + 127u) / 255u);
          }
          q[3] = 255;
        }
      }
    }
  }
  return sheet;
}

}  // namespace toond::cli::gallery
