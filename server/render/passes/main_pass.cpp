#include "render/frame/texture_unit.h"
#include "render/passes/passes.h"

namespace toond::render {
namespace {

// The shading program's features for one material, on top of the frame's.
ToonVariant material_variant(const FrameContext& frame, const GpuMaterial& material, const DrawnMaterial& drawn) {
  ToonVariant variant = frame.plan.shading;
  // An unlit material shows its base colour as it is: the flat mode.
  if (material.unlit) variant.set_mode(ToonFeature::ModeFlat);
  const bool shaped = drawn.cuts || drawn.blended;
  // A cut-out or blended material's texture gives its shape: it is sampled
  // even where the request leaves textures out (base white).
  variant.set(ToonFeature::HasTexture, (frame.plan.sample_textures || shaped) && drawn.has_texture());
  variant.set(ToonFeature::AlphaMask, drawn.cuts);
  variant.set(ToonFeature::AlphaBlend, drawn.blended);
  // A matte material (specular.source: material) has no highlight.
  if (!drawn.specular) variant.set(ToonFeature::Specular, false);
  variant.set(ToonFeature::NormalMap, frame.plan.use_normal_maps && material.normal_texture >= 0);
  // A shade colour changes nothing where nothing is lit to blend from.
  variant.set(ToonFeature::ShadeColor,
              frame.params.shade_colors.contains(material.name) && frame.params.mode != ShadingMode::Flat);
  return variant;
}

// Which of an object's submeshes a draw takes: the opaque and cut-out ones
// first, then, over them, the blended ones.
enum class Layering { Solid, Blended };

// Object i, submesh by submesh, each with its material's program and
// block; a program is switched only where the variant changes. With
// `viewer`, runs of faces that surely turn away from it are left out.
void shade_object(PassContext& context, std::size_t i, const std::optional<MeshViewer>& viewer, Layering layering) {
  const FrameContext& frame = context.frame;
  const GpuModel& model = context.model(i);
  const gpu::Program* in_use = nullptr;
  const std::vector<scene::Submesh>& submeshes = model.submeshes(frame.lod_of(i));
  for (std::size_t k = 0; k < submeshes.size(); ++k) {
    const scene::Submesh& sub = submeshes[k];
    const DrawnMaterial& drawn = frame.material(i, sub.material);
    if (drawn.blended != (layering == Layering::Blended)) continue;
    const GpuMaterial& material = model.materials()[static_cast<std::size_t>(sub.material)];
    const ToonVariant variant = material_variant(frame, material, drawn);
    gpu::Program& program = context.programs.get("toon.vert", "toon.frag", variant.defines());
    if (&program != in_use) program.use();
    in_use = &program;
    bind_material(context, i, sub.material);
    if (variant.has(ToonFeature::NormalMap)) {
      glBindTextureUnit(texture_unit::kNormalMap, model.texture(material.normal_texture));
    }
    // A request's colour for one material's darkest band, by its name.
    if (variant.has(ToonFeature::ShadeColor)) program.set("u_shade_color", frame.params.shade_colors.at(material.name));
    if (viewer)
      context.main_triangles_skipped += model.draw_facing(frame.lod_of(i), k, *viewer, context.pacing);
    else
      model.draw(sub, context.pacing);
  }
}

// The blended materials, over everything solid: farthest object first,
// both sides of their faces (one sees the far side through the near), the
// depth tested but not written, so each shows what lies behind it.
void draw_blended(PassContext& context) {
  const FrameContext& frame = context.frame;
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    const auto& materials = frame.materials[i];
    if (std::none_of(materials.begin(), materials.end(), [](const DrawnMaterial& m) { return m.blended; })) continue;
    order.emplace_back(-frame.view_depths[i], i);
  }
  if (order.empty()) return;
  std::sort(order.begin(), order.end());
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  for (const auto& [distance, i] : order) {
    context.blocks.bind_object(i);
    context.model(i).bind();
    cull(HiddenFaces::None);
    shade_object(context, i, std::nullopt, Layering::Blended);
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace

std::optional<MeshViewer> turned_away_runs_viewer(const PassContext& context, std::size_t i) {
  const FrameContext& frame = context.frame;
  const glm::dmat4& placement = frame.scene.matrices[i];
  const bool mirrored = glm::determinant(glm::dmat3(placement)) < 0.0;
  const HiddenFaces turned_away = mirrored ? HiddenFaces::Front : HiddenFaces::Back;
  if (!context.skip_turned_away_runs || frame.main_faces[i].hidden != turned_away) return std::nullopt;
  return viewer_in_mesh(placement, frame.viewer, frame.world_per_px_at_w1());
}

// Shades every object, and (where the plan has a hull outline) marks every
// covered sample in the stencil so the hull can only land outside the model.
void draw_main_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const RenderParams& params = frame.params;
  context.target->bind_for_drawing();
  glEnable(GL_FRAMEBUFFER_SRGB);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  if (frame.plan.stencil_mark)
    glEnable(GL_STENCIL_TEST);
  else
    glDisable(GL_STENCIL_TEST);
  glStencilMask(0xff);
  // The lines layer holds nothing but lines: the background is for the
  // color render they are laid over.
  const glm::vec4 clear = frame.plan.output == Output::Lines ? glm::vec4(0.0f) : params.background;
  glClearColor(clear.r, clear.g, clear.b, clear.a);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  context.main_cap_checks.resize(frame.objects.size());
  if (frame.shadow) glBindTextureUnit(texture_unit::kShadowMap, context.resources.shadow_map().texture());
  // Where a cap shows, the side culled is drawn after all: whole.
  draw_objects(
      context,
      {.faces = [&](std::size_t i) { return frame.main_faces[i]; },
       .draw = [&](std::size_t i) { shade_object(context, i, turned_away_runs_viewer(context, i), Layering::Solid); },
       .redraw = [&](std::size_t i) { shade_object(context, i, std::nullopt, Layering::Solid); },
       .cap_checks = &context.main_cap_checks});
  draw_blended(context);
}

}  // namespace toond::render
