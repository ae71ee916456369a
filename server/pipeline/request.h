#pragma once
// A render request on its way through the pipeline (pipeline.h): what was
// asked, typed and completed, then resolved against the stored models.
#include <cstddef>
#include <optional>
#include <vector>

#include "pipeline/output_png.h"
#include "render/render_params.h"
#include "render/render_service.h"
#include "render/sheet_layout.h"
#include "scene/model_pins.h"

namespace toond::pipeline {

struct Request {
  render::RenderParams params;
  // The models drawn, each with its transform: a lone model (or the demo)
  // at the identity, or the objects of a scene. Their poses are the
  // frames' own (pose.h), not set here.
  std::vector<render::JobObject> objects;
  // A sheet's tiles and each frame's view; none for a single image, which
  // is drawn as one frame of the request's own parameters.
  std::optional<render::SheetLayout> layout;
  // `animation`'s clip, looked up in the model (clips.h).
  std::optional<std::size_t> clip;
  OutputDescription output;
  // Where the models are pinned (resolve.h); leased when the frames are
  // queued, so that every replica sees them in use.
  scene::ModelPins* pins = nullptr;
};

}  // namespace toond::pipeline
