#include "support/surface_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toond::test {
namespace {

glm::dvec3 nearest_on_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  if (!(length2 > 0.0)) return a;
  return a + ab * std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0);
}

struct Ball {
  glm::dvec3 centre;
  double radius;
};

Ball ball_around(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 centre = (a + b + c) / 3.0;
  return {centre, std::max({glm::length(a - centre), glm::length(b - centre), glm::length(c - centre)})};
}

}  // namespace

glm::dvec3 nearest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  // Inside the prism over the triangle the nearest point is p's drop onto
  // its plane; outside it, the nearest point lies on an edge.
  const glm::dvec3 normal = glm::cross(b - a, c - a);
  const double area2 = glm::dot(normal, normal);
  if (area2 > 0.0) {
    const glm::dvec3 dropped = p - normal * (glm::dot(p - a, normal) / area2);
    const double u = glm::dot(glm::cross(c - b, dropped - b), normal);
    const double v = glm::dot(glm::cross(a - c, dropped - c), normal);
    const double w = glm::dot(glm::cross(b - a, dropped - a), normal);
    if (u >= 0.0 && v >= 0.0 && w >= 0.0) return dropped;
  }
  glm::dvec3 best = nearest_on_segment(p, a, b);
  for (const glm::dvec3& q : {nearest_on_segment(p, b, c), nearest_on_segment(p, c, a)}) {
    if (glm::length(p - q) < glm::length(p - best)) best = q;
  }
  return best;
}

std::vector<double> distances_to_surface(std::span<const glm::dvec3> points, std::span<const glm::dvec3> vertices,
                                         std::span<const std::uint32_t> indices) {
  std::vector<Ball> balls;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    balls.push_back(ball_around(vertices[indices[t]], vertices[indices[t + 1]], vertices[indices[t + 2]]));
  }
  std::vector<double> distances;
  distances.reserve(points.size());
  for (const glm::dvec3& p : points) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < balls.size(); ++t) {
      // A triangle inside a ball farther away than the best so far cannot
      // come nearer.
      if (glm::length(p - balls[t].centre) - balls[t].radius >= best) continue;
      const glm::dvec3 q = nearest_on_triangle(p, vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
                                               vertices[indices[3 * t + 2]]);
      best = std::min(best, glm::length(p - q));
    }
    distances.push_back(best);
  }
  return distances;
}

}  // namespace toond::test
