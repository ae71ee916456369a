#pragma once
// `sheet.pack`: every tile of an assembled sheet cut to its visible pixels
// (tile_trim.h) and packed into a smaller image (skyline_pack.h), and the
// atlas pointed into it the way TexturePacker's and Aseprite's trimmed
// exports say it: `frame` the packed rectangle, `trimmed`,
// `spriteSourceSize` where that rectangle lies in the tile, `sourceSize`
// the tile. Anchors stay what they were: fractions of the tile, which
// Phaser and PixiJS apply to `sourceSize`. Placed at spriteSourceSize in a
// sourceSize canvas, each packed frame is its tile again, pixel for pixel
// (fully transparent pixels all read (0, 0, 0, 0)).
#include <span>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "sheet_files/skyline_pack.h"

namespace toond::sheet_files {

// Replaces each of `layers` (the sheets of a sheet's layers, laid out
// alike: one for a sheet of one layer) with its packed image and rewrites
// `atlas` (its frames' rectangles and meta.size; meta.columns and
// meta.rows go, since the tiles no longer stand in a grid, and meta.packed
// is true). Each tile is cut to the pixels of all the layers, so the
// layers' packed images share the atlas and overlay as their sheets did. A
// tile with no visible pixel keeps one transparent pixel: engines refuse
// frames of no size.
void pack_sheet(std::span<image::Image* const> layers, nlohmann::ordered_json& atlas, const PackOptions& options);

// A sheet of one layer.
inline void pack_sheet(image::Image& sheet, nlohmann::ordered_json& atlas, const PackOptions& options) {
  image::Image* const one[] = {&sheet};
  pack_sheet(one, atlas, options);
}

}  // namespace toond::sheet_files
