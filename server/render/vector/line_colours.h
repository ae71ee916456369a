#pragma once
// The colour each line of a drawing takes, as the request's PNG draws it:
// the outline's colour (the contour's where contour lines alone draw the
// silhouettes), except that with `outline.color_mode` material or texture
// the hull and the wireframe draw silhouettes and open edges in the colour
// of the surface beside them: its material's colour darkened, or its
// texture there inverted and darkened. A vector stroke has one colour per
// mesh edge, so the texture is averaged along the edge where the PNG
// varies along it. Crease and seam lines keep the outline's colour, as
// the crease and edge passes draw them.
#include <cstdint>
#include <vector>

#include "render/plan/frame_plan.h"
#include "render/vector/line_candidates.h"
#include "render/vector/svg_document.h"
#include "render/vector/view_mesh.h"

namespace toond::render::vector {

// The colour every line of `plan` takes unless its surface gives it one.
Srgb fixed_line_colour(const FramePlan& plan);

class LineColours {
 public:
  // `mesh`: the frame's triangles as view_mesh_of placed them for `plan`;
  // both must outlive this.
  LineColours(const FramePlan& plan, const ViewMesh& mesh);

  // The drawing's own colour, which every line takes unless its surface
  // gives it one.
  Srgb fixed() const { return fixed_; }
  // Whether some lines take their surface's colour.
  bool per_surface() const { return source_ != Source::Fixed; }
  Srgb of(const Segment& segment) const;

 private:
  enum class Source { Fixed, Material, Texture };
  // One submesh of an object's drawn level: its triangles from `first` on.
  struct MaterialRun {
    std::uint32_t first = 0;
    int material = 0;
  };

  std::size_t object_of(std::uint32_t triangle) const;
  int material_of(std::size_t object, std::uint32_t triangle) const;
  glm::vec3 texture_colour(std::size_t object, const DrawnMaterial& drawn, std::uint32_t triangle,
                           const Segment& segment) const;
  Srgb surface_colour(const Segment& segment) const;

  const FramePlan& plan_;
  const ViewMesh& mesh_;
  Source source_ = Source::Fixed;
  Srgb fixed_{0, 0, 0};
  float keep_ = 1;                              // 1 - darken
  std::vector<std::vector<MaterialRun>> runs_;  // per object, by first triangle
};

}  // namespace toond::render::vector
