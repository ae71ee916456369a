#pragma once
// What a render of a mesh will cost does not follow from its triangle count:
// sixty thousand large faces stacked on one another cover the frame sixty
// thousand times, while a million small ones of a scan cover it about twice.
// Import measures what sets the cost of rasterising a mesh once it is
// framed, so a request can be priced, for its own view, before anything is
// drawn.
#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace toond::scene {

class RenderCostProfile {
 public:
  // The triangles' area vectors (area × unit normal) summed in bins by
  // direction: each normal is turned into the half space of its largest
  // component (|n·v| does not tell n from -n) and binned on that face of a
  // cube, kBinsPerSide² bins a face. Within a bin the normals differ by a
  // few degrees at most, so the sum's |A·v| stands for the bin's Σ|a·v|.
  static constexpr int kBinsPerSide = 16;
  static constexpr int kBins = 3 * kBinsPerSide * kBinsPerSide;

  RenderCostProfile() = default;
  RenderCostProfile(const std::array<glm::dvec3, kBins>& area_bins, const glm::dvec3& extent, double edge_span);

  // Layers of surface a ray along `view` (any length but zero) through the
  // model's bounds meets on average, front and back faces alike (as a pass
  // that culls nothing draws them): the triangles' areas projected along
  // it over the area the bounding box projects to. A closed convex body
  // measures 1.5–2, a scan 2–4; n coincident faces filling the bounds, n.
  double layers_toward(const glm::dvec3& view) const;
  // The most layers over a fixed spread of 48 directions: what a view of
  // unknown direction (a scene of turned objects) is priced at, and what
  // the upload answer reports.
  double layers() const { return max_layers_; }
  // The triangles' longest edges added up, in units of the bounding box's
  // diagonal: how many frame-widths of edge a pass rasterises. A rasteriser
  // pays for the screen tiles a triangle crosses, not only for the pixels
  // it covers, so a sheet of thin slivers across the frame costs by this
  // figure where its area says nothing.
  double edge_span() const { return edge_span_; }

 private:
  std::array<glm::vec3, kBins> area_bins_{};
  glm::dvec3 extent_{0.0};
  double edge_span_ = 0;
  double max_layers_ = 0;
};

// The profile of the triangles `indices` over `positions`; `extent` is the
// size of the positions' bounding box. Independent of the mesh's place and
// scale. Linear in the triangle count.
RenderCostProfile measure_render_cost(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                      const glm::vec3& extent);

}  // namespace toond::scene
