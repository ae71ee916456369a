#include <optional>
#include <span>

#include "render/passes/outline_colour.h"
#include "render/passes/passes.h"

namespace toond::render {
namespace {

// What object i's cull reads, or nullopt where its whole hull is drawn:
// the cull is off, the object is posed (its vertices are not the ones kept
// on the CPU), or a material is cut out by its alpha (the main pass then
// leaves samples of its faces unmarked), or the level's cull mesh is
// still being built (the first frame asks for it).
std::optional<HullCullInput> cull_input(const PassContext& context, std::size_t i) {
  const FrameContext& frame = context.frame;
  const GpuModel& model = context.model(i);
  if (!context.cull_hull || !frame.plan.stencil_mark || context.frame.has_cutouts(i)) return std::nullopt;
  std::shared_ptr<const HullCullMesh> mesh = model.hull_cull_mesh(frame.lod_of(i), context.background);
  if (!mesh) return std::nullopt;
  const glm::dmat4& placement = frame.scene.matrices[i];
  HullCullView view;
  view.model = placement;
  view.normal_matrix = glm::transpose(glm::inverse(glm::dmat3(placement)));
  view.clip = frame.clip;
  view.width_px = frame.outline_px;
  view.world_per_px_at_w1 = frame.world_per_px_at_w1();
  view.viewport_width = frame.draw_width;
  view.viewport_height = frame.draw_height;
  view.drawn_clockwise = frame.main_faces[i].hidden == HiddenFaces::Front;
  view.hull_hidden = frame.hull_faces[i].hidden;
  view.count_layers = frame.plan.samples > 1;
  return HullCullInput{std::move(mesh), view};
}

// Every object's faces that may show, in one element buffer.
struct HullFaces {
  std::vector<std::optional<HullSubset>> subsets;
  std::vector<std::size_t> first;  // where each object's indices start in the buffer
  const gpu::Buffer* buffer = nullptr;
};

HullFaces hull_faces(PassContext& context) {
  HullFaces out;
  out.subsets = context.hull_cull.valid() ? context.hull_cull.take()
                                          : std::vector<std::optional<HullSubset>>(context.frame.objects.size());
  std::vector<std::span<const std::uint32_t>> parts;
  std::size_t count = 0;
  for (const std::optional<HullSubset>& subset : out.subsets) {
    out.first.push_back(count);
    if (!subset) continue;
    context.hull_faces_culled += subset->culled_triangles;
    context.hull_faces_turned_away += subset->turned_away_triangles();
    parts.push_back(subset->indices);
    count += parts.back().size();
  }
  if (count > 0) out.buffer = &context.resources.hull_indices(parts);
  return out;
}

// Which of the hull's sides a draw shows: the one its culling keeps, or
// both (its skipped side drawn after all, where a cap shows).
enum class HullSide { Shown, Both };

// Object i's hull: only the faces that may show where they were worked out,
// and of those, the ones set apart as turned to the culled side only where
// that side is drawn.
void draw_hull_of(const PassContext& context, const HullFaces& faces, std::size_t i, HullSide side) {
  const bool per_material = outline_per_material(context.frame);
  const std::optional<HullSubset>& subset = faces.subsets[i];
  if (!subset) {
    if (per_material)
      draw_by_material(context, i);
    else
      draw_whole_object(context, i);
    return;
  }
  const GpuModel& model = context.model(i);
  const bool both = side == HullSide::Both;
  if (!per_material) {
    const std::size_t count = both ? subset->indices.size() : subset->facing_index_count();
    if (count > 0) model.draw_from(*faces.buffer, count, faces.first[i], context.pacing);
    return;
  }
  const auto draw_range = [&](const scene::Submesh& sub) {
    if (sub.index_count == 0) return;
    bind_material(context, i, sub.material);
    model.draw_from(*faces.buffer, sub.index_count, faces.first[i] + sub.first_index, context.pacing);
  };
  for (std::size_t k = 0; k < subset->submeshes.size(); ++k) {
    draw_range(subset->submeshes[k]);
    if (both && k < subset->turned_away.size()) draw_range(subset->turned_away[k]);
  }
}

}  // namespace

// The inverted hull, outside the stencil mark the main pass left.
void draw_hull_outline_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  context.target->bind_for_drawing();
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gpu::Program& program = context.programs.get("hull.vert", "hull.frag", frame.plan.outline.defines());
  program.use();
  const HullFaces faces = hull_faces(context);
  draw_objects(context, {.faces = [&](std::size_t i) { return frame.hull_faces[i]; },
                         .draw = [&](std::size_t i) { draw_hull_of(context, faces, i, HullSide::Shown); },
                         .redraw = [&](std::size_t i) { draw_hull_of(context, faces, i, HullSide::Both); }});
}

void start_hull_cull(PassContext& context) {
  std::vector<std::optional<HullCullInput>> inputs;
  bool any = false;
  for (std::size_t i = 0; i < context.frame.objects.size(); ++i) {
    inputs.push_back(cull_input(context, i));
    any = any || inputs.back().has_value();
  }
  if (!any) return;
  // Off the render thread, which records the main pass meanwhile (on a CPU
  // rasterizer that mostly takes longer than this), or on it if the main
  // pass was recorded first.
  context.hull_cull = Handoff<std::vector<std::optional<HullSubset>>>(context.background, [inputs = std::move(inputs)] {
    std::vector<std::optional<HullSubset>> subsets;
    for (const std::optional<HullCullInput>& input : inputs) {
      subsets.push_back(input ? hull_faces_that_may_show(*input->mesh, input->view) : std::nullopt);
    }
    return subsets;
  });
}

}  // namespace toond::render
