#include "render/plan/face_culling.h"

#include <algorithm>
#include <limits>

namespace toond::render {

HiddenFaces hidden_faces(scene::Enclosure enclosure, const glm::dmat4& model, const glm::dmat4& view_projection,
                         const scene::Bounds& bounds, double reach) {
  if (enclosure == scene::Enclosure::Open) return HiddenFaces::None;
  // The box in the scene, grown by `reach`.
  glm::dvec3 low(std::numeric_limits<double>::max());
  glm::dvec3 high(std::numeric_limits<double>::lowest());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 q(model * glm::dvec4(bounds.corner(corner), 1.0));
    low = glm::min(low, q - reach);
    high = glm::max(high, q + reach);
  }
  for (int corner = 0; corner < 8; ++corner) {
    // The grown box stays in double: scene coordinates may be large.
    const glm::dvec3 p((corner & 1) ? high.x : low.x, (corner & 2) ? high.y : low.y, (corner & 4) ? high.z : low.z);
    const glm::dvec4 c = view_projection * glm::dvec4(p, 1.0);
    // Inside the depth range: -w <= z <= w with w > 0 (x and y may leave
    // the view; cutting at the image's sides opens nothing that shows).
    if (!(c.w > 0.0) || c.z < -c.w || c.z > c.w) return HiddenFaces::None;
  }
  // GL's projections flip handedness (eye space looks down -z, depth grows
  // into the screen): a determinant of the opposite sign to the model's
  // keeps counter-clockwise faces counter-clockwise on screen.
  const bool mirrored = (glm::determinant(glm::dmat3(model)) < 0.0) == (glm::determinant(view_projection) < 0.0);
  const bool outward = enclosure == scene::Enclosure::Outward;
  return outward != mirrored ? HiddenFaces::Back : HiddenFaces::Front;
}

bool caps_face_away(const std::vector<glm::vec3>& caps, scene::Enclosure enclosure, const glm::dmat4& model,
                    const Viewer& viewer) {
  // Any cap turned away proves the point; the margin only keeps rounding
  // from deciding a cap seen exactly edge-on.
  constexpr double kMargin = 1e-6;
  // The caps are wound like the mesh; a mirror or an inside-out mesh turns
  // their cross product inward.
  const bool mirrored = glm::determinant(glm::dmat3(model)) < 0.0;
  const double outward = (mirrored != (enclosure == scene::Enclosure::Inward)) ? -1.0 : 1.0;
  for (std::size_t t = 0; t + 2 < caps.size(); t += 3) {
    const glm::dvec3 a(model * glm::dvec4(glm::dvec3(caps[t]), 1.0));
    const glm::dvec3 b(model * glm::dvec4(glm::dvec3(caps[t + 1]), 1.0));
    const glm::dvec3 c(model * glm::dvec4(glm::dvec3(caps[t + 2]), 1.0));
    const glm::dvec3 n = glm::cross(b - a, c - a) * outward;
    const double area = glm::length(n);
    const double size = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    if (!(area > 1e-12 * size * size)) continue;
    const glm::dvec3 ray = viewer.orthographic ? viewer.forward : (a + b + c) / 3.0 - viewer.eye;
    const double ray_length = glm::length(ray);
    if (!(ray_length > 0.0)) return false;
    if (glm::dot(n, ray) / (area * ray_length) < kMargin) return false;
  }
  return true;
}

}  // namespace toond::render
