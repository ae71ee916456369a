#pragma once
// Renders a request in the test process, on the test's GL context, the way
// the daemon would: the request completed by the schema (preset expanded,
// defaults filled in), the models uploaded, one Renderer with the embedded
// shaders.
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "image/image.h"
#include "render/render_params.h"
#include "scene/model.h"

namespace toond::test {

// The parameters the daemon would render `request` with.
render::RenderParams complete_params(const nlohmann::json& request);

// Each model drawn with its transform.
using PlacedModels = std::vector<std::pair<const scene::Model*, glm::dmat4>>;
image::Image render_in_process(const PlacedModels& models, const nlohmann::json& request);
image::Image render_in_process(const scene::Model& model, const nlohmann::json& request);

}  // namespace toond::test
