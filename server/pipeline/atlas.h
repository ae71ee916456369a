#pragma once
// A sheet's atlas (render/atlas/sheet_atlas.h), written from its layout and
// its frames' plans, without rendering: the answer of ?atlas=json, and the
// tEXt chunk of a sheet's PNG.
#include <nlohmann/json.hpp>

#include <vector>
#include "pipeline/request.h"

#include "render/plan/frame_plan.h"

namespace toond::pipeline {

// `plans`: the sheet's frames' (plan.h), in layout order.
nlohmann::ordered_json atlas_of(const Request& request, const std::vector<render::FramePlan>& plans);

}  // namespace toond::pipeline
