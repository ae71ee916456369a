#include "render/renderer.h"

#include <chrono>

#include "gpu/gpu_error.h"
#include "render/camera.h"

namespace toond::render {
namespace {

using Clock = std::chrono::steady_clock;

class PassTimer {
 public:
  explicit PassTimer(std::vector<PassTiming>& out) : out_(out) {}
  void mark(Pass pass) {
    const auto now = Clock::now();
    out_.push_back({pass_name(pass), std::chrono::duration<double, std::milli>(now - start_).count()});
    start_ = now;
  }

 private:
  std::vector<PassTiming>& out_;
  Clock::time_point start_ = Clock::now();
};

void check_gl(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw gpu::GpuError(std::string("GL error 0x") + std::to_string(error) + " in " + where);
  }
}

}  // namespace

gpu::RenderTarget& Renderer::target_for(int width, int height, int samples) {
  if (!target_ || !target_->matches(width, height, samples)) {
    target_.reset();  // free the old storage before allocating the new
    target_.emplace(width, height, samples);
  }
  return *target_;
}

RenderOutput Renderer::render(const GpuModel& model, const RenderParams& params) {
  const PassPlan plan = plan_passes(params, {model.has_textures()});
  RenderOutput out;
  out.plan = plan.describe();
  PassTimer timer(out.timings);

  gpu::RenderTarget& target = target_for(params.width, params.height, plan.samples);
  target.bind_for_drawing();
  const CameraSetup camera = fit_camera(params.camera, model.bounds(),
                                        static_cast<double>(params.width) / params.height);
  const glm::mat4 view_projection = camera.view_projection();

  glEnable(GL_FRAMEBUFFER_SRGB);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xff);
  glClearColor(params.background.r, params.background.g, params.background.b, params.background.a);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  model.bind();

  // Main pass: shade, and mark every covered sample in the stencil so the
  // hull outline can only land outside the model.
  {
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    std::vector<glm::vec3> light_to;
    std::vector<glm::vec3> light_color;
    for (const DirectionalLight& l : params.lights) {
      const double len = glm::length(l.direction);
      // A zero direction has no way to travel; it lights nothing.
      if (!(len > 0.0)) continue;
      light_to.push_back(glm::vec3(-l.direction / len));
      light_color.push_back(l.color);
    }
    for (const scene::Submesh& sub : model.submeshes()) {
      const GpuMaterial& material = model.materials()[static_cast<std::size_t>(sub.material)];
      std::vector<std::string> defines = plan.main_defines;
      const bool textured = plan.sample_textures && material.texture >= 0;
      if (textured) defines.push_back("HAS_TEXTURE");
      gpu::Program& program = programs_.get("toon.vert", "toon.frag", defines);
      program.use();
      program.set("u_view_projection", view_projection);
      program.set("u_base_color", material.diffuse);
      program.set("u_ambient", params.ambient);
      program.set("u_steps", static_cast<float>(params.steps));
      program.set("u_light_count", static_cast<int>(light_to.size()));
      program.set_array("u_light_to", light_to);
      program.set_array("u_light_color", light_color);
      if (textured) {
        glBindTextureUnit(0, model.texture(material.texture));
        program.set("u_diffuse_map", 0);
      }
      model.draw(sub);
    }
    check_gl("main pass");
    timer.mark(Pass::Main);
  }

  if (plan.has(Pass::HullOutline)) {
    glStencilFunc(GL_NOTEQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    gpu::Program& program = programs_.get("hull.vert", "hull.frag", {});
    program.use();
    program.set("u_view_projection", view_projection);
    // projection[1][1] maps a view-space height at depth w to NDC, and NDC
    // spans `height` pixels over 2 units.
    const double world_per_px = 2.0 / (camera.projection[1][1] * params.height);
    program.set("u_world_per_px_at_w1", static_cast<float>(world_per_px));
    program.set("u_width_px", params.outline.width_px);
    program.set("u_outline_color", params.outline.color);
    model.draw_all();
    check_gl("hull outline pass");
    timer.mark(Pass::HullOutline);
  }

  glBindVertexArray(0);
  glDisable(GL_STENCIL_TEST);
  // The multisample resolve is a blit inside read_back(); its time is part
  // of the readback figure, since the readback waits for it anyway.
  out.image = target.read_back();
  check_gl("readback");
  timer.mark(Pass::Readback);
  return out;
}

}  // namespace toond::render
