#pragma once
// How far points lie from a triangle surface: what a level of detail's
// error promises, checked in whatever pose its vertices are in.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace toond::test {

// The point of triangle (a, b, c) nearest to p (the triangle may be thin or
// a point).
glm::dvec3 nearest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// For each of `points`, its distance to the nearest of the triangles
// `indices` makes of `vertices`.
std::vector<double> distances_to_surface(std::span<const glm::dvec3> points, std::span<const glm::dvec3> vertices,
                                         std::span<const std::uint32_t> indices);

}  // namespace toond::test
