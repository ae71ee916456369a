#include "render/plan/line_drawing_cost.h"

#include <cmath>

namespace toond::render {

RenderCost line_drawing_cost(const RenderParams& params, std::span<const scene::Mesh* const> meshes) {
  RenderCost cost;
  // Without an outline or contour lines there is nothing to look for.
  if (!params.outline.any() && !params.contour.enabled) return cost;
  const double angle = params.outline.crease_angle_deg;
  for (const scene::Mesh* mesh : meshes) {
    const double triangles = static_cast<double>(mesh->triangle_count());
    cost.line_triangles += triangles;
    // A view's silhouettes cross a mesh about as often as a line across it
    // crosses triangles: a few times the square root of their count.
    cost.line_edges += kSilhouetteEdgesPerRootTriangle * std::sqrt(triangles) +
                       static_cast<double>(mesh->crease_edges.creased_at(angle)) +
                       static_cast<double>(mesh->intersections.creased_at(angle));
  }
  return cost;
}

}  // namespace toond::render
