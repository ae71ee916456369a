#pragma once
// Analytic answers for line drawings: which points of a scene of boxes, or
// of a torus, an eye sees, and where a torus's contour (where its surface
// turns edge-on to the eye) runs; with the camera a drawing's metadata
// holds (svg_drawing.h), so a test can lay the exact lines over the drawn
// ones. Ray casting against the shapes themselves, not their meshes.
#include <functional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "support/svg_drawing.h"

namespace toond::test {

struct MetaCamera {
  glm::dmat4 view{1.0}, projection{1.0};
  int width = 0, height = 0;
  bool orthographic = false;
  glm::dvec3 eye{0.0};      // perspective
  glm::dvec3 forward{0.0};  // the view's direction (every ray's, orthographic)

  glm::dvec2 project(const glm::dvec3& p) const;
  // The ray through pixel px: a point on it near the eye and its direction.
  std::pair<glm::dvec3, glm::dvec3> ray_through(glm::dvec2 px) const;
  // Where a ray toward p starts: the eye, or far back along the view.
  glm::dvec3 ray_origin(const glm::dvec3& p, double far) const;
};
MetaCamera camera_from_metadata(const nlohmann::json& camera);

struct Box {
  glm::dvec3 lo, hi;
};
// The 12 edges of a box.
std::vector<std::pair<glm::dvec3, glm::dvec3>> box_edges(const Box& box);
// Whether the ray through pixel px meets a box.
bool ray_meets_boxes(const MetaCamera& camera, const std::vector<Box>& boxes, glm::dvec2 px);
// Whether p, on a box's surface, is seen: no box is entered on the way to it.
bool seen_among_boxes(const MetaCamera& camera, const std::vector<Box>& boxes, const glm::dvec3& p);

// A torus about the y axis: its ring of radius `major` in the xz plane,
// its tube of radius `minor`.
struct Torus {
  double major = 1, minor = 0.35;
  double distance(const glm::dvec3& p) const;  // signed, as a distance field
};
bool seen_on_torus(const MetaCamera& camera, const Torus& torus, const glm::dvec3& p);
// Whether the ray through pixel px meets the torus.
bool ray_meets_torus(const MetaCamera& camera, const Torus& torus, glm::dvec2 px);
// The torus's normal at a point of its surface.
glm::dvec3 torus_normal(const Torus& torus, const glm::dvec3& p);
// Points of the torus's contour, `around` values of the ring's angle apart,
// and its cusps: where the contour, followed from one ring angle to the
// next, turns back on screen (there a surface of facets, whose contour
// runs along its edges, parts from the smooth one by more than its facets'
// error elsewhere).
struct TorusContourPoints {
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec3> cusps;
};
TorusContourPoints torus_contour(const MetaCamera& camera, const Torus& torus, int around);

// A 3D line sampled evenly: each sample on screen and whether it is seen.
struct SampledLine {
  std::vector<glm::dvec2> at;
  std::vector<bool> seen;
  double seen_share() const;
};
SampledLine sample_line(const MetaCamera& camera, const glm::dvec3& a, const glm::dvec3& b,
                        const std::function<bool(const glm::dvec3&)>& seen, int samples);
// The seen stretches of lines on screen, as segments between neighbouring seen samples.
std::vector<std::pair<glm::dvec2, glm::dvec2>> seen_stretches(const std::vector<SampledLine>& lines);

// Points along drawn strokes, at most `step` pixels apart.
std::vector<glm::dvec2> points_along(const std::vector<SvgStroke>& strokes, double step);

// What share of a line's seen samples lie within `reach` pixels of `drawn`.
double covered_share(const SampledLine& line, const std::vector<std::pair<glm::dvec2, glm::dvec2>>& drawn,
                     double reach);

// Whether p lies inside the convex hull of `points`, at least `inset`
// pixels in from each of its sides.
bool inside_hull(std::vector<glm::dvec2> points, glm::dvec2 p, double inset);

}  // namespace toond::test
