#pragma once
// A sheet's atlas (render/atlas/sheet_atlas.h), written from its layout and the
// framing its frames share, without rendering: the answer of ?atlas=json,
// and the tEXt chunk of a sheet's PNG.
#include <nlohmann/json.hpp>

#include "pipeline/request.h"
#include "render/plan/camera.h"

namespace toond::pipeline {

// `scene`: the framing every frame of the sheet shares (plan.h).
nlohmann::ordered_json atlas_of(const Request& request, const render::SceneFrame& scene);

}  // namespace toond::pipeline
