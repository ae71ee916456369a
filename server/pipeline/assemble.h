#pragma once
// The frames of a request, as they come back from the render threads, put
// together into one render's output. A single image is its one frame as
// drawn. A sheet's tiles are laid into one image, padding and empty tiles
// transparent (a data layer's in floats until it is encoded, so a depth
// sheet has one range over every frame); `sheet.animate` keeps the frames
// apart instead, for the animated WebP. With `sheet.pixel_art` each frame
// was drawn at 1/scale: all are quantised to one palette (the given one, or
// one computed over every frame, so nothing flickers as the model turns),
// then blown up into their tiles. A sheet drawn as several layers
// (sheet_layers.h) is laid out once per layer, each quantised on its own.
#include <cstddef>
#include <optional>
#include <vector>

#include "image/image.h"
#include "render/frame/render_output.h"
#include "render/plan/render_params.h"
#include "render/plan/sheet_layout.h"

namespace toond::pipeline {

class Assembly {
 public:
  // `layout`: the request's sheet; none for a single image. `layers`: how
  // many layers each of its frames is drawn as.
  Assembly(const render::RenderParams& params, const std::optional<render::SheetLayout>& layout,
           std::size_t layers = 1);

  // Frame `index` of the layout (0 for a single image; layer l's frame i at
  // l × frames + i), in any order: each goes into place as soon as it is
  // done, and its own image is let go while the next frame renders.
  void add(std::size_t index, render::RenderOutput frame);

  // Once every frame is in: the first layer's sheet as `image`, the others'
  // as `other_layers`. `timings` add up each pass over the frames (and
  // pixel art's palette and upscaling, as `pixel_art`); `lods` give per
  // object the finest level any frame drew (and "both" faces when any frame
  // drew both); `plan` and `samples` are the first layer's frames' own.
  render::RenderOutput finish();

 private:
  const render::RenderParams& params_;
  const std::optional<render::SheetLayout>& layout_;
  std::size_t layers_;
  render::RenderOutput out_;
  std::vector<image::Image> art_tiles_;  // pixel art: the small frames, layer after layer, until all are in

  image::Image& layer_sheet(std::size_t layer);
};

}  // namespace toond::pipeline
