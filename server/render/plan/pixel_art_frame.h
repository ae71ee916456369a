#pragma once
// How a pixel-art sheet's tile is drawn (`sheet.pixel_art`): small, and
// with nothing that blends colours, so every art pixel is one colour of
// the scene that the shared palette then snaps; and with lines as a sprite
// artist draws them unless the request keeps its own.
#include "render/plan/render_params.h"

namespace toond::render {

// With lines sprite, crease and inner lines are drawn only between areas
// at least this many art pixels across: with a 1-pixel line between them,
// each keeps two pixels of its own colour.
inline constexpr int kReadableAreaArtPx = 3;

// `frame` (one frame's parameters, as frame_params gives them) drawn at
// 1/scale of its size, one sample a pixel, band edges hard, and its lines
// as `art.lines` says. `art.scale` divides width and height (the pipeline
// checks).
RenderParams pixel_art_frame_params(RenderParams frame, const SheetParams::PixelArt& art);

}  // namespace toond::render
