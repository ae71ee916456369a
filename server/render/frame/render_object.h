#pragma once
// One object of a frame on the render thread: its GPU copy (posed as the
// job says, GpuModel::apply_pose), the model it was made from, and, for a
// frame planned from these objects (Renderer::render with parameters),
// where it stands and its pose's framing.
#include <memory>

#include <glm/glm.hpp>

#include "render/frame/gpu_model.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::render {

struct RenderObject {
  const GpuModel& gpu;
  const scene::Model& model;
  glm::dmat4 transform{1.0};                      // model → scene coordinates; the identity for a lone model
  std::shared_ptr<const scene::SkinPose> pose{};  // null: as imported
};

}  // namespace toond::render
