#pragma once
// A sprite sheet's frames rendered and laid into one image. The frames are
// queued together (RenderService::submit_all), each a render of its own
// view under the framing shared by all (render/sheet_layout.h).
#include <chrono>
#include <memory>
#include <vector>

#include "http/service_context.h"
#include "render/camera.h"
#include "render/render_service.h"
#include "render/sheet_layout.h"

namespace toond::http {

// The models of the job as the framing sees them, the same as the render
// thread does: the atlas reports that framing without rendering.
render::SceneFrame scene_of(const render::RenderJob& job);

// The sheet as one render's output: `image` (or, for a data layer,
// `layer`) is the whole sheet, padding and empty tiles transparent; for
// `sheet.animate`, `frames` holds the frames instead and there is no sheet;
// `timings` add up each pass over the frames; `lods` give per object the finest level any frame drew (and "both" faces
// when any frame drew both), `plan` and `samples` are the frames' own.
// With `sheet.pixel_art` each frame is drawn at 1/scale, all are quantised to
// one palette (the given one, or one computed over every frame), then blown
// up into their tiles; the time that takes is the timing `pixel_art`. An
// animated sheet draws frame i in poses[i] (http/animation_pose.h); empty
// `poses`: every frame in the job's own.
render::RenderOutput render_sheet(ServiceContext& context, const render::RenderJob& job,
                                  const render::SheetLayout& layout,
                                  const std::vector<std::shared_ptr<const scene::SkinPose>>& poses,
                                  std::chrono::steady_clock::time_point deadline);

}  // namespace toond::http
