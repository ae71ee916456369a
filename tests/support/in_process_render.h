#pragma once
// Renders a request in the test process, on the test's GL context, the way
// the daemon would: the request completed by the schema (preset expanded,
// defaults filled in), the models uploaded, one Renderer with the embedded
// shaders.
#include <memory>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "gpu/program_cache.h"
#include "image/image.h"
#include "render/frame/gpu_model.h"
#include "render/plan/render_params.h"
#include "render/run/renderer.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::test {

// The parameters the daemon would render `request` with.
render::RenderParams complete_params(const nlohmann::json& request);

// Each model drawn with its transform.
using PlacedModels = std::vector<std::pair<const scene::Model*, glm::dmat4>>;
image::Image render_in_process(const PlacedModels& models, const nlohmann::json& request);

// The models uploaded and one Renderer with the embedded shaders, kept for
// tests that render the same scene more than once, a switch of the
// renderer's flipped in between.
class InProcessScene {
 public:
  explicit InProcessScene(const PlacedModels& models);
  render::Renderer& renderer() { return renderer_; }
  // Object i drawn in `pose` from the next render on (nullptr: at rest).
  void pose(std::size_t i, std::shared_ptr<const scene::SkinPose> pose);
  render::RenderOutput render(const render::RenderParams& params) { return renderer_.render(objects_, params); }

 private:
  gpu::ProgramCache programs_;
  render::Renderer renderer_;
  std::vector<std::unique_ptr<render::GpuModel>> uploaded_;
  std::vector<render::RenderObject> objects_;
};
image::Image render_in_process(const scene::Model& model, const nlohmann::json& request);

}  // namespace toond::test
