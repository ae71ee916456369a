#pragma once
// How far points are from a triangle soup: the distance of each point to
// the nearest point of any triangle, through a bounding-volume tree so a
// few thousand points against a few thousand triangles stays cheap.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace toond::test {

// The point of triangle (a, b, c) nearest to p.
glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c);

class SurfaceDistance {
 public:
  // Triangles as index triples into `positions`; both are copied.
  SurfaceDistance(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> indices);

  // The distance from p to the nearest triangle (infinity when there is none).
  double distance(const glm::dvec3& p) const;

 private:
  struct Node {
    glm::dvec3 min, max;
    std::uint32_t first = 0;  // a leaf's first triangle in order_; an inner node's left child
    std::uint32_t count = 0;  // a leaf's triangles; 0 for an inner node
    std::uint32_t right = 0;  // an inner node's right child
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);

  std::vector<glm::dvec3> corners_;   // three per triangle
  std::vector<std::uint32_t> order_;  // triangle indices, grouped by leaf
  std::vector<Node> nodes_;
};

}  // namespace toond::test
