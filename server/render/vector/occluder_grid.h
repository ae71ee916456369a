#pragma once
// What may hide a line, found by where it lies on screen: every triangle
// that may hide something (ViewMesh::hides) with the planes that say which
// points it hides, binned over a grid of screen cells by its box, so that
// a segment meets only the triangles whose boxes share a cell with it.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/vector/screen_map.h"
#include "render/vector/view_mesh.h"

namespace toond::render::vector {

// A triangle hides the points of view space that its cone from the eye
// holds (the three planes through the eye and its sides, or along the view
// direction in an orthographic view) and that lie behind its own plane: four
// half-spaces, each plane.xyz · p + plane.w > 0 (unit normals, so the
// value is a distance). Along a segment each is linear, so the part of it
// a triangle hides is one interval.
struct Occluder {
  std::array<glm::dvec4, 4> planes;
  std::array<std::uint32_t, 3> groups;     // its corners' welded positions
  std::uint8_t shared_sides = 0;           // ViewMesh::shared_sides
  float near_depth = 0;                    // the least depth (-z) of its corners
  glm::vec2 box_min{0.0f}, box_max{0.0f};  // on screen, pixels
};

// What a caller of OccluderGrid::gather keeps between calls (one a thread):
// which occluders it has taken for the current segment.
struct GatherScratch {
  std::vector<std::uint32_t> seen;
  std::uint32_t mark = 0;
};

class OccluderGrid {
 public:
  // `margin`: pixels around the image where lines are still drawn.
  OccluderGrid(const ViewMesh& mesh, const ScreenMap& screen, double margin);

  // The occluders whose boxes share a cell with the segment from p to q
  // (pixels), each once, in `out` (cleared first).
  void gather(glm::dvec2 p, glm::dvec2 q, std::vector<std::uint32_t>& out, GatherScratch& scratch) const;
  const Occluder& occluder(std::uint32_t i) const { return occluders_[i]; }
  // The depth (-z) where the ray through pixel `px` first meets an
  // occluder; negative where it meets none. `nearby`, `scratch`: scratch space.
  double first_depth(glm::dvec2 px, const ScreenMap& screen, std::vector<std::uint32_t>& nearby,
                     GatherScratch& scratch) const;
  std::size_t size() const { return occluders_.size(); }

 private:
  // Each hiding triangle's occluder, worked out over the cores, kept in the
  // triangles' order; returns the cells each covers (none where it hides
  // nothing after all, or lies off the drawn area, or reaches behind the
  // eye: then it is in everywhere_).
  std::vector<glm::ivec4> place(const ViewMesh& mesh, const ScreenMap& screen);
  // The occluders listed in the cells they cover.
  void bin(const std::vector<glm::ivec4>& ranges);
  // The cells' columns and rows a box covers, clamped to the grid.
  glm::ivec4 cell_range(glm::dvec2 lo, glm::dvec2 hi) const;

  std::vector<Occluder> occluders_;
  std::vector<std::uint32_t> everywhere_;  // occluders reaching behind the eye: their boxes are unbounded
  glm::dvec2 origin_{0.0};                 // the grid's corner, pixels
  double cell_ = 1;                        // a cell's side, pixels
  int columns_ = 1, rows_ = 1;
  std::vector<std::uint32_t> cell_start_;  // per cell, into cell_items_ (one more at the end)
  std::vector<std::uint32_t> cell_items_;
};

// The occluder of the triangle (a, b, c) in view space, or false where it
// hides nothing (no area, or seen edge-on).
bool make_occluder(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, bool orthographic, Occluder& out);

}  // namespace toond::render::vector
