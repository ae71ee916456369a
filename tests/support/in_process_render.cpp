#include "support/in_process_render.h"

#include <memory>
#include <string>

#include "gpu/program_cache.h"
#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "presets.h"
#include "render/frame/gpu_model.h"
#include "render/run/renderer.h"
#include "toond_shader_files.h"

namespace toond::test {

render::RenderParams complete_params(const nlohmann::json& request) {
  const nlohmann::json completed =
      proto::ParamSchema::render_params().validate_and_complete(proto::Presets::builtin().expand(request));
  return pipeline::render_params_from_wire(completed);
}

InProcessScene::InProcessScene(const PlacedModels& models)
    : programs_([](const std::string& name) { return std::string(shader_files::find(name)); }), renderer_(programs_) {
  for (const auto& [model, transform] : models) {
    uploaded_.push_back(std::make_unique<render::GpuModel>(*model));
    objects_.push_back({*uploaded_.back(), *model, transform});
  }
}

void InProcessScene::pose(std::size_t i, std::shared_ptr<const scene::SkinPose> pose) {
  uploaded_[i]->apply_pose(pose, objects_[i].model);
  objects_[i].pose = std::move(pose);
}

image::Image render_in_process(const PlacedModels& models, const nlohmann::json& request) {
  return InProcessScene(models).render(complete_params(request)).image;
}

image::Image render_in_process(const scene::Model& model, const nlohmann::json& request) {
  return render_in_process(PlacedModels{{&model, glm::dmat4(1.0)}}, request);
}

}  // namespace toond::test
