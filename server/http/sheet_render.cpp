#include "http/sheet_render.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <vector>

#include "http/render_wait.h"
#include "image/block_upscale.h"
#include "image/palette_quantise.h"
#include "render/pass_plan.h"
#include "render/pixel_art_frame.h"

namespace toond::http {
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
std::vector<image::Rgb8> sheet_palette(const std::vector<image::Image>& tiles,
                                       const render::SheetParams::PixelArt& pixel_art) {
  std::vector<image::Rgb8> palette;
  for (const auto& [r, g, b] : pixel_art.palette) palette.push_back({r, g, b});
  if (!palette.empty()) return palette;
  std::vector<const image::Image*> all;
  for (const image::Image& tile : tiles) all.push_back(&tile);
  return image::median_cut_palette(all, pixel_art.colors);
}

// Quantises the small tiles to the sheet's palette (in place) and puts each,
// blown up by the scale, into its place in the sheet, or, for an
// animation, into a frame of its own.
void finish_pixel_art(std::vector<image::Image>& tiles, const render::SheetParams& params,
                      const render::SheetLayout& layout, render::RenderOutput& sheet) {
  const render::SheetParams::PixelArt& pixel_art = *params.pixel_art;
  const std::vector<image::Rgb8> palette = sheet_palette(tiles, pixel_art);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    // No palette only when no tile has a visible pixel: nothing to change.
    if (!palette.empty()) image::quantise_to_palette(tiles[i], palette, pixel_art.dither);
    if (params.animate) {
      image::Image& frame = sheet.frames.emplace_back(image::Image{
          layout.tile_width, layout.tile_height,
          std::vector<std::uint8_t>(static_cast<std::size_t>(layout.tile_width) * layout.tile_height * 4, 0)});
      image::blit_upscaled(tiles[i], pixel_art.scale, frame, 0, 0);
    } else {
      image::blit_upscaled(tiles[i], pixel_art.scale, sheet.image, layout.frames[i].x, layout.frames[i].y);
    }
  }
}

}  // namespace

render::SceneFrame scene_of(const render::RenderJob& job) {
  std::vector<render::ScenePart> parts;
  for (const render::JobObject& o : job.objects) {
    const scene::Mesh& mesh = o.model->mesh;
    // A posed object is framed as its pose says (a whole clip's reach).
    if (o.pose) {
      parts.push_back({o.pose->bounds, mesh.origin, o.transform, o.pose->extremes});
    } else {
      parts.push_back({mesh.bounds, mesh.origin, o.transform, mesh.extremes});
    }
  }
  return render::frame_scene(parts);
}

namespace {

// The order the frames are drawn in: the layout's, except that frames
// sharing a pose (an animated sheet's directions of one time) follow each
// other, so the GPU copy poses once for all of them (GpuModel::apply_pose).
std::vector<std::size_t> render_order(const render::SheetLayout& layout,
                                      const std::vector<std::shared_ptr<const scene::SkinPose>>& poses) {
  std::vector<std::size_t> order(layout.frames.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (poses.empty()) return order;
  std::map<const scene::SkinPose*, std::size_t> first_use;
  for (std::size_t i = 0; i < order.size(); ++i) first_use.emplace(poses[i].get(), i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return first_use[poses[a].get()] < first_use[poses[b].get()]; });
  return order;
}

}  // namespace

render::RenderOutput render_sheet(ServiceContext& context, const render::RenderJob& job,
                                  const render::SheetLayout& layout,
                                  const std::vector<std::shared_ptr<const scene::SkinPose>>& poses,
                                  std::chrono::steady_clock::time_point deadline) {
  const std::optional<render::SheetParams::PixelArt>& pixel_art = job.params.sheet->pixel_art;
  const std::vector<std::size_t> order = render_order(layout, poses);
  std::vector<render::RenderJob> frames;
  for (const std::size_t index : order) {
    const render::SheetFrame& frame = layout.frames[index];
    render::RenderJob one;
    one.objects = job.objects;
    if (!poses.empty()) one.objects.front().pose = poses[static_cast<std::size_t>(frame.index)];
    one.params = render::frame_params(job.params, layout, frame);
    if (pixel_art) one.params = render::pixel_art_frame_params(std::move(one.params), *pixel_art);
    one.deadline = deadline;
    // The sheet waits in the lane its whole price says, its client's turn.
    one.client = job.client;
    one.cost = job.cost;
    one.paced_chunk_triangles = job.paced_chunk_triangles;
    one.paced_band_texels = job.paced_band_texels;
    frames.push_back(std::move(one));
  }
  std::vector<std::future<render::RenderOutput>> futures = context.renderer.submit_all(std::move(frames));

  render::RenderOutput sheet;
  const bool animate = job.params.sheet->animate;
  const std::size_t values = static_cast<std::size_t>(layout.width) * layout.height * 4;
  // A data layer's sheet stays in floats until it is encoded, so that a
  // depth sheet has one range over every frame. An animation keeps its
  // frames apart and lays out no sheet.
  if (render::is_data_layer(job.params.output)) {
    sheet.layer = {layout.width, layout.height, std::vector<float>(values, 0.0f)};
  } else if (!animate) {
    sheet.image = {layout.width, layout.height, std::vector<std::uint8_t>(values, 0)};
  }
  // Pixel art: the small frames, until all are in; an animation: its frames.
  std::vector<image::Image> art_tiles(pixel_art ? layout.frames.size() : 0);
  if (animate && !pixel_art) sheet.frames.resize(layout.frames.size());
  for (std::size_t i = 0; i < futures.size(); ++i) {
    // Each tile goes into place as soon as it is done, and its own image
    // is let go while the next frame renders.
    render::RenderOutput frame = await_render(futures[i], wait_limit(job, deadline), context.render_deadline);
    const std::size_t index = order[i];
    if (pixel_art) {
      art_tiles[index] = std::move(frame.image);
    } else if (animate) {
      sheet.frames[index] = std::move(frame.image);
    } else if (render::is_data_layer(job.params.output)) {
      copy_tile(frame.layer, layout.frames[index], sheet.layer);
    } else {
      copy_tile(frame.image, layout.frames[index], sheet.image);
    }
    add_timings(frame.timings, sheet.timings);
    merge_lods(frame.lods, sheet.lods);
    sheet.plan = frame.plan;
    sheet.samples = frame.samples;
  }
  if (pixel_art) {
    // After the last frame: one palette needs every frame's colours.
    const auto start = std::chrono::steady_clock::now();
    finish_pixel_art(art_tiles, *job.params.sheet, layout, sheet);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    sheet.timings.push_back({"pixel_art", ms, false, ms});
  }
  return sheet;
}

}  // namespace toond::http
