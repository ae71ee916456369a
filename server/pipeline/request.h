#pragma once
// A render request on its way through the pipeline (pipeline.h): what was
// asked, typed and completed, then resolved against the stored models.
#include <cstddef>
#include <optional>
#include <vector>

#include "pipeline/clips.h"
#include "pipeline/output_png.h"
#include "pipeline/sheet_answer.h"
#include "render/plan/render_params.h"
#include "render/plan/sheet_layout.h"
#include "render/run/render_service.h"
#include "scene/store/model_pins.h"

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
  // `animation`'s clip and the part of it that plays, looked up in the
  // model (clips.h).
  std::optional<AnimationClip> clip;
  OutputDescription output;
  // What a sheet answers (?atlas=…): its image unless the route says
  // otherwise.
  SheetAnswer answer;
  // Where the models are pinned (resolve.h); leased when the frames are
  // queued, so that every replica sees them in use.
  scene::ModelPins* pins = nullptr;
};

}  // namespace toond::pipeline
