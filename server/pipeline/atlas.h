#pragma once
// A sheet's atlas (render/sheet_atlas.h), written from its layout and the
// framing its frames share, without rendering: the answer of ?atlas=json,
// and the tEXt chunk of a sheet's PNG.
#include <nlohmann/json.hpp>

#include "pipeline/pose.h"
#include "pipeline/request.h"

namespace toond::pipeline {

// `poses`: the first frame's (pose.h), whose framing every frame shares.
nlohmann::json atlas_of(const Request& request, const ObjectPoses& poses);

}  // namespace toond::pipeline
