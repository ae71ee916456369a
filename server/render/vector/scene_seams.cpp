#include "render/vector/scene_seams.h"

#include <algorithm>
#include <limits>

#include "scene/mesh/intersection_lines.h"

namespace toond::render::vector {
namespace {

struct Box {
  glm::dvec3 lo{std::numeric_limits<double>::max()};
  glm::dvec3 hi{std::numeric_limits<double>::lowest()};
  void add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool overlaps(const Box& o) const {
    return glm::all(glm::lessThanEqual(lo, o.hi)) && glm::all(glm::lessThanEqual(o.lo, hi));
  }
};

Box triangle_box(const ViewMesh& mesh, std::size_t t) {
  Box box;
  for (int k = 0; k < 3; ++k) box.add(mesh.corner(t, k));
  return box;
}

Box object_box(const ViewMesh& mesh, const ViewObject& object) {
  Box box;
  for (std::size_t t = object.first_triangle; t < object.first_triangle + object.triangle_count; ++t) {
    const Box b = triangle_box(mesh, t);
    box.add(b.lo);
    box.add(b.hi);
  }
  return box;
}

// Triangles of two objects as one soup: each corner its own vertex, with
// its face's normal (the turn across a seam is between the faces), the
// first object's part 0, the second's part 1.
struct Soup {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices, parts;

  void add(const ViewMesh& mesh, std::size_t t, std::uint32_t part) {
    const glm::dvec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (!(length > 0)) return;
    for (const glm::dvec3& p : {a, b, c}) {
      indices.push_back(static_cast<std::uint32_t>(positions.size()));
      positions.emplace_back(p);
      normals.emplace_back(n / length);
      parts.push_back(part);
    }
  }
};

// Object o's triangles that reach into `other`.
void add_reaching(const ViewMesh& mesh, const ViewObject& o, const Box& other, std::uint32_t part, Soup& soup) {
  for (std::size_t t = o.first_triangle; t < o.first_triangle + o.triangle_count; ++t) {
    if (triangle_box(mesh, t).overlaps(other)) soup.add(mesh, t, part);
  }
}

}  // namespace

std::vector<std::pair<glm::dvec3, glm::dvec3>> scene_seams(const ViewMesh& mesh, double crease_angle_deg) {
  std::vector<std::pair<glm::dvec3, glm::dvec3>> seams;
  std::vector<Box> boxes;
  for (const ViewObject& o : mesh.objects) boxes.push_back(object_box(mesh, o));
  for (std::size_t i = 0; i < mesh.objects.size(); ++i) {
    for (std::size_t j = i + 1; j < mesh.objects.size(); ++j) {
      if (!boxes[i].overlaps(boxes[j])) continue;
      Soup soup;
      add_reaching(mesh, mesh.objects[i], boxes[j], 0, soup);
      add_reaching(mesh, mesh.objects[j], boxes[i], 1, soup);
      if (soup.indices.empty()) continue;
      const scene::IntersectionLines lines =
          scene::find_intersection_lines(soup.positions, soup.normals, soup.indices, soup.parts);
      const std::size_t count = lines.creased_at(crease_angle_deg);
      for (std::size_t k = 0; k < count; ++k) {
        seams.emplace_back(glm::dvec3(lines.points[4 * k + 1]), glm::dvec3(lines.points[4 * k + 2]));
      }
    }
  }
  return seams;
}

}  // namespace toond::render::vector
