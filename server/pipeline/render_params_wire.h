#pragma once
// The wire form of render parameters turned into the renderer's resolved,
// typed values: the pipeline's entry (render_entry.h) takes the completed
// JSON and turns it here, so render/ sees only RenderParams, never the
// request text, and the HTTP layer never sees RenderParams.
#include <nlohmann/json.hpp>

#include "render/plan/render_params.h"

namespace toond::pipeline {

// `completed` is a request that ParamSchema::validate_and_complete() has
// checked and filled with the schema's defaults (presets already expanded),
// so every field is present and in range. Colours become linear, a light's
// intensity is folded into its colour, ramp stops are sorted, and a sheet's
// absent fields are taken from the camera.
render::RenderParams render_params_from_wire(const nlohmann::json& completed);

}  // namespace toond::pipeline
