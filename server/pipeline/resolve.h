#pragma once
// The pipeline's first stage: a request's parameters resolved against the
// store and the daemon's size limits, before the result cache is asked and
// before anything is posed, priced or drawn.
#include "pipeline/render_limits.h"
#include "pipeline/request.h"
#include "render/plan/render_params.h"
#include "scene/store/model_library.h"
#include "scene/store/model_pins.h"

namespace toond::pipeline {

// In this order, each failure an error naming the field at fault: the
// sheet's own consistency (sheet_checks.h), the models (404 unknown_model
// at /model or /objects/N/model; none: the demo model), an animated sheet's
// clips (clips.h), the size limits (budget.h), the output's ids
// (output_png.h), the bundle images the parameters name (422 missing_file
// or bad_image at /shading/ramp_image, /floor/texture), the sheet's layout,
// and `animation`'s clip.
// The models are pinned in `pins` (scene/store/model_pins.h), which the caller
// keeps until the answer is sent; the request leases them when queued.
Request resolve(render::RenderParams params, scene::ModelLibrary& library, scene::ModelPins& pins,
                const RenderLimits& limits);

}  // namespace toond::pipeline
