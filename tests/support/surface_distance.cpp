#include "support/surface_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toond::test {
namespace {

constexpr std::uint32_t kLeafTriangles = 4;

double box_distance2(const glm::dvec3& p, const glm::dvec3& min, const glm::dvec3& max) {
  const glm::dvec3 outside = glm::max(glm::max(min - p, p - max), glm::dvec3(0.0));
  return glm::dot(outside, outside);
}

}  // namespace

// The nearest point is a corner, a point of an edge or a point inside,
// told apart by where p projects in the triangle's barycentric
// coordinates (the Voronoi regions of its corners and edges).
glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double sum = va + vb + vc;
  if (!(sum > 0)) return a;  // a degenerate triangle: its corners were tried
  return a + ab * (vb / sum) + ac * (vc / sum);
}

SurfaceDistance::SurfaceDistance(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> indices) {
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    for (std::size_t k = 0; k < 3; ++k) corners_.push_back(positions[indices[i + k]]);
  }
  const auto triangles = static_cast<std::uint32_t>(corners_.size() / 3);
  order_.resize(triangles);
  for (std::uint32_t t = 0; t < triangles; ++t) order_[t] = t;
  if (triangles > 0) build(0, triangles);
}

// The node over triangles order_[first, first + count): a leaf, or split at
// the median of the triangles' centres along the box's longest side.
std::uint32_t SurfaceDistance::build(std::uint32_t first, std::uint32_t count) {
  const auto self = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::uint32_t i = first; i < first + count; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      lo = glm::min(lo, corners_[3 * order_[i] + k]);
      hi = glm::max(hi, corners_[3 * order_[i] + k]);
    }
  }
  nodes_[self].min = lo;
  nodes_[self].max = hi;
  if (count <= kLeafTriangles) {
    nodes_[self].first = first;
    nodes_[self].count = count;
    return self;
  }
  const glm::dvec3 size = hi - lo;
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
  const auto centre = [&](std::uint32_t t) {
    return corners_[3 * t][axis] + corners_[3 * t + 1][axis] + corners_[3 * t + 2][axis];
  };
  const std::uint32_t half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](std::uint32_t l, std::uint32_t r) { return centre(l) < centre(r); });
  const std::uint32_t left = build(first, half);
  const std::uint32_t right = build(first + half, count - half);
  nodes_[self].first = left;
  nodes_[self].right = right;
  return self;
}

double SurfaceDistance::distance(const glm::dvec3& p) const {
  double best2 = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) return best2;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (box_distance2(p, node.min, node.max) >= best2) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const std::size_t t = order_[i];
        const glm::dvec3 q = closest_point_on_triangle(p, corners_[3 * t], corners_[3 * t + 1], corners_[3 * t + 2]);
        best2 = std::min(best2, glm::dot(p - q, p - q));
      }
      continue;
    }
    // The nearer child last, so it is searched first.
    const double l = box_distance2(p, nodes_[node.first].min, nodes_[node.first].max);
    const double r = box_distance2(p, nodes_[node.right].min, nodes_[node.right].max);
    stack.push_back(l < r ? node.right : node.first);
    stack.push_back(l < r ? node.first : node.right);
  }
  return std::sqrt(best2);
}

}  // namespace toond::test
