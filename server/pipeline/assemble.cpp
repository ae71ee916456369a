#include "pipeline/assemble.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <span>

#include "image/block_upscale.h"
#include "image/palette_quantise.h"
#include "render/plan/pass_plan.h"

namespace toond::pipeline {
namespace {

// Image or FloatImage: four values a pixel, rows top to bottom.
template <class Pixels>
void copy_tile(const Pixels& tile, const render::SheetFrame& frame, Pixels& sheet) {
  const std::size_t row_bytes = static_cast<std::size_t>(tile.width) * 4 * sizeof(*tile.pixel(0, 0));
  for (int y = 0; y < tile.height; ++y) {
    std::memcpy(sheet.pixel(frame.x, frame.y + y), tile.pixel(0, y), row_bytes);
  }
}

void add_timings(const std::vector<render::PassTiming>& frame, std::vector<render::PassTiming>& total) {
  for (const render::PassTiming& t : frame) {
    auto same = std::find_if(total.begin(), total.end(), [&](const render::PassTiming& s) { return s.pass == t.pass; });
    if (same == total.end()) {
      total.push_back(t);
    } else {
      same->ms += t.ms;
      same->cpu_ms += t.cpu_ms;
    }
  }
}

// The header reports what the sheet as a whole may show: the finest level
// and the most faces any frame drew.
void merge_lods(const std::vector<render::LodUse>& frame, std::vector<render::LodUse>& sheet) {
  if (sheet.empty()) {
    sheet = frame;
    return;
  }
  for (std::size_t i = 0; i < sheet.size() && i < frame.size(); ++i) {
    const render::HiddenFaces culled =
        frame[i].culled == render::HiddenFaces::None ? render::HiddenFaces::None : sheet[i].culled;
    if (frame[i].level < sheet[i].level) sheet[i] = frame[i];
    sheet[i].culled = culled;
  }
}

// The palette a pixel-art sheet is quantised to: the one asked for, or one
// computed over every tile at once, so a colour is the same entry in every
// frame and nothing flickers as the model turns.
std::vector<image::Rgb8> sheet_palette(std::span<const image::Image> tiles,
                                       const render::SheetParams::PixelArt& pixel_art) {
  std::vector<image::Rgb8> palette;
  for (const auto& [r, g, b] : pixel_art.palette) palette.push_back({r, g, b});
  if (!palette.empty()) return palette;
  std::vector<const image::Image*> all;
  for (const image::Image& tile : tiles) all.push_back(&tile);
  return image::median_cut_palette(all, pixel_art.colors);
}

// Quantises one layer's small tiles to its palette (in place) and puts
// each, blown up by the scale, into its place in the layer's sheet, or, for
// an animation, into a frame of its own.
void finish_pixel_art(std::span<image::Image> tiles, const render::SheetParams& params,
                      const render::SheetLayout& layout, image::Image& sheet, std::vector<image::Image>& frames) {
  const render::SheetParams::PixelArt& pixel_art = *params.pixel_art;
  const std::vector<image::Rgb8> palette = sheet_palette(tiles, pixel_art);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    // No palette only when no tile has a visible pixel: nothing to change.
    if (!palette.empty()) image::quantise_to_palette(tiles[i], palette, pixel_art.dither);
    if (params.animate) {
      image::Image& frame = frames.emplace_back(image::Image{
          layout.tile_width, layout.tile_height,
          std::vector<std::uint8_t>(static_cast<std::size_t>(layout.tile_width) * layout.tile_height * 4, 0)});
      image::blit_upscaled(tiles[i], pixel_art.scale, frame, 0, 0);
    } else {
      image::blit_upscaled(tiles[i], pixel_art.scale, sheet, layout.frames[i].x, layout.frames[i].y);
    }
  }
}

}  // namespace

Assembly::Assembly(const render::RenderParams& params, const std::optional<render::SheetLayout>& layout,
                   std::size_t layers)
    : params_(params), layout_(layout), layers_(layers) {
  if (!layout_) return;
  const render::SheetParams& sheet = *params_.sheet;
  const std::size_t values = static_cast<std::size_t>(layout_->width) * layout_->height * 4;
  if (render::is_data_layer(params_.output)) {
    out_.layer = {layout_->width, layout_->height, std::vector<float>(values, 0.0f)};
  } else if (!sheet.animate) {
    out_.image = {layout_->width, layout_->height, std::vector<std::uint8_t>(values, 0)};
    out_.other_layers.assign(layers_ - 1, out_.image);
  }
  if (sheet.pixel_art) {
    art_tiles_.resize(layout_->frames.size() * layers_);
  } else if (sheet.animate) {
    out_.frames.resize(layout_->frames.size());
  }
}

void Assembly::add(std::size_t index, render::RenderOutput frame) {
  if (!layout_) {
    out_ = std::move(frame);
    return;
  }
  const std::size_t layer = index / layout_->frames.size();
  const std::size_t tile = index % layout_->frames.size();
  if (params_.sheet->pixel_art) {
    art_tiles_[index] = std::move(frame.image);
  } else if (params_.sheet->animate) {
    out_.frames[tile] = std::move(frame.image);
  } else if (render::is_data_layer(params_.output)) {
    copy_tile(frame.layer, layout_->frames[tile], out_.layer);
  } else {
    copy_tile(frame.image, layout_->frames[tile], layer_sheet(layer));
  }
  add_timings(frame.timings, out_.timings);
  merge_lods(frame.lods, out_.lods);
  if (layer > 0) return;
  out_.plan = frame.plan;
  out_.samples = frame.samples;
}

render::RenderOutput Assembly::finish() {
  if (layout_ && params_.sheet->pixel_art) {
    // After the last frame: one palette needs every frame's colours.
    const auto start = std::chrono::steady_clock::now();
    const std::size_t frames = layout_->frames.size();
    for (std::size_t layer = 0; layer < layers_; ++layer) {
      const std::span<image::Image> tiles(art_tiles_.data() + layer * frames, frames);
      finish_pixel_art(tiles, *params_.sheet, *layout_, layer_sheet(layer), out_.frames);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    out_.timings.push_back({"pixel_art", ms, false, ms});
  }
  return std::move(out_);
}

image::Image& Assembly::layer_sheet(std::size_t layer) {
  return layer == 0 ? out_.image : out_.other_layers[layer - 1];
}

}  // namespace toond::pipeline
