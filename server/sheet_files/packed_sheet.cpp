#include "sheet_files/packed_sheet.h"

#include <cstring>

#include "sheet_files/atlas_view.h"
#include "sheet_files/tile_trim.h"

namespace toond::sheet_files {
namespace {

using json = nlohmann::ordered_json;

json rect_json(int x, int y, int w, int h) { return {{"x", x}, {"y", y}, {"w", w}, {"h", h}}; }

void copy_rect(const image::Image& from, const PixelRect& rect, image::Image& to, const PackPlace& at) {
  const std::size_t row_bytes = static_cast<std::size_t>(rect.w) * 4;
  for (int y = 0; y < rect.h; ++y) std::memcpy(to.pixel(at.x, at.y + y), from.pixel(rect.x, rect.y + y), row_bytes);
}

}  // namespace

void pack_sheet(std::span<image::Image* const> layers, nlohmann::ordered_json& atlas, const PackOptions& options) {
  const AtlasView view = view_of(atlas);
  const std::vector<const image::Image*> sheets(layers.begin(), layers.end());
  std::vector<PixelRect> kept;
  std::vector<PackSize> sizes;
  for (const AtlasFrame& frame : view.frames) {
    PixelRect bounds = visible_bounds(sheets, frame.frame);
    if (bounds.w == 0) bounds = {frame.frame.x, frame.frame.y, 1, 1};
    kept.push_back(bounds);
    sizes.push_back({bounds.w, bounds.h});
  }
  const Packing packing = pack_rects(sizes, options);
  const image::Image blank{packing.width, packing.height,
                           std::vector<std::uint8_t>(static_cast<std::size_t>(packing.width) * packing.height * 4, 0)};
  std::vector<image::Image> packed(layers.size(), blank);
  json& frames = atlas.at("frames");
  for (std::size_t i = 0; i < view.frames.size(); ++i) {
    const AtlasFrame& frame = view.frames[i];
    const PixelRect& bounds = kept[i];
    const PackPlace& place = packing.places[i];
    for (std::size_t l = 0; l < layers.size(); ++l) copy_rect(*layers[l], bounds, packed[l], place);
    json& entry = frames.at(frame.name);
    entry["frame"] = rect_json(place.x, place.y, bounds.w, bounds.h);
    entry["trimmed"] = bounds.w != frame.tile_w || bounds.h != frame.tile_h;
    entry["spriteSourceSize"] = rect_json(bounds.x - frame.frame.x + frame.source.x,
                                          bounds.y - frame.frame.y + frame.source.y, bounds.w, bounds.h);
  }
  json& meta = atlas.at("meta");
  meta["size"] = {{"w", packing.width}, {"h", packing.height}};
  meta.erase("columns");
  meta.erase("rows");
  meta["packed"] = true;
  for (std::size_t l = 0; l < layers.size(); ++l) *layers[l] = std::move(packed[l]);
}

}  // namespace toond::sheet_files
