#include "http/sheet_render.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "http/render_wait.h"
#include "render/pass_plan.h"

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

}  // namespace

render::SceneFrame scene_of(const render::RenderJob& job) {
  std::vector<render::ScenePart> parts;
  for (const render::JobObject& o : job.objects) {
    const scene::Mesh& mesh = o.model->mesh;
    parts.push_back({mesh.bounds, mesh.origin, o.transform, mesh.extremes});
  }
  return render::frame_scene(parts);
}

render::RenderOutput render_sheet(ServiceContext& context, const render::RenderJob& job,
                                  const render::SheetLayout& layout, std::chrono::steady_clock::time_point deadline) {
  std::vector<render::RenderJob> frames;
  for (const render::SheetFrame& frame : layout.frames) {
    render::RenderJob one;
    one.objects = job.objects;
    one.params = render::frame_params(job.params, layout, frame);
    one.deadline = deadline;
    frames.push_back(std::move(one));
  }
  std::vector<std::future<render::RenderOutput>> futures = context.renderer.submit_all(std::move(frames));

  render::RenderOutput sheet;
  const std::size_t values = static_cast<std::size_t>(layout.width) * layout.height * 4;
  // A data layer's sheet stays in floats until it is encoded, so that a
  // depth sheet has one range over every frame.
  if (render::is_data_layer(job.params.output)) {
    sheet.layer = {layout.width, layout.height, std::vector<float>(values, 0.0f)};
  } else {
    sheet.image = {layout.width, layout.height, std::vector<std::uint8_t>(values, 0)};
  }
  for (std::size_t i = 0; i < futures.size(); ++i) {
    // Each tile goes into place as soon as it is done, and its own image
    // is let go while the next frame renders.
    const render::RenderOutput frame = await_render(futures[i], deadline, context.render_deadline);
    if (render::is_data_layer(job.params.output)) copy_tile(frame.layer, layout.frames[i], sheet.layer);
    else copy_tile(frame.image, layout.frames[i], sheet.image);
    add_timings(frame.timings, sheet.timings);
    merge_lods(frame.lods, sheet.lods);
    sheet.plan = frame.plan;
    sheet.samples = frame.samples;
  }
  return sheet;
}

}  // namespace toond::http
