#include "scene/mesh/crease_profile.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "scene/mesh/flat_map.h"
#include "scene/mesh/mesh_processing.h"

namespace toond::scene {
namespace {

// The first triangle side seen on an edge, waiting for its neighbour.
struct OpenSide {
  std::uint32_t at_low;   // the side's vertex at the edge's lower position group
  std::uint32_t at_high;  // and at its higher one
  std::uint32_t triangle;
  bool matched = false;
};

double angle_deg(const glm::vec3& a, const glm::vec3& b) {
  const double c = std::clamp(static_cast<double>(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::acos(-1.0);
}

}  // namespace

double CreaseProfile::at(double degrees) const {
  const auto d = static_cast<std::size_t>(std::clamp(std::floor(degrees), 0.0, 180.0));
  return fraction_over[d];
}

double CreaseProfile::lines_area(double degrees) const {
  const auto d = static_cast<std::size_t>(std::clamp(std::floor(degrees), 0.0, 180.0));
  return lines_area_over[d];
}

bool CreaseProfile::hard_edged(double degrees) const {
  return at(degrees) >= kHardEdgedShare || lines_area(degrees) >= kHardEdgedShare;
}

namespace {

// One creased edge between two triangles: its position groups, length,
// triangles, and the largest whole degree its turn exceeds.
struct CreasedEdge {
  std::uint32_t low = 0, high = 0;
  double length = 0;
  std::size_t triangles[2] = {0, 0};
  std::size_t degree = 0;
};

// Creased edges joined into lines as the crease angle falls: a union-find
// over position groups whose sets carry their length and the triangles
// beside them; a set that reaches `line_length` counts its triangles'
// area, each triangle once.
class CreaseLines {
 public:
  CreaseLines(std::size_t groups, std::span<const double> areas, double line_length)
      : parent_(groups),
        length_(groups, 0.0),
        beside_(groups),
        areas_(areas),
        counted_(areas.size(), false),
        line_length_(line_length) {
    for (std::size_t g = 0; g < groups; ++g) parent_[g] = static_cast<std::uint32_t>(g);
  }

  void add(const CreasedEdge& edge) {
    std::uint32_t root = join(find(edge.low), find(edge.high));
    length_[root] += edge.length;
    for (const std::size_t tri : edge.triangles) beside_[root].push_back(tri);
    if (length_[root] >= line_length_) count(root);
  }

  double counted_area() const { return counted_area_; }

 private:
  std::uint32_t find(std::uint32_t g) {
    while (parent_[g] != g) g = parent_[g] = parent_[parent_[g]];
    return g;
  }

  // The larger list absorbs the smaller: each triangle moves O(log n) times.
  std::uint32_t join(std::uint32_t a, std::uint32_t b) {
    if (a == b) return a;
    if (beside_[a].size() < beside_[b].size()) std::swap(a, b);
    parent_[b] = a;
    length_[a] += length_[b];
    beside_[a].insert(beside_[a].end(), beside_[b].begin(), beside_[b].end());
    std::vector<std::size_t>().swap(beside_[b]);
    return a;
  }

  void count(std::uint32_t root) {
    for (const std::size_t tri : beside_[root]) {
      if (counted_[tri]) continue;
      counted_[tri] = true;
      counted_area_ += areas_[tri];
    }
    beside_[root].clear();  // counted; later triangles are counted as they come
  }

  std::vector<std::uint32_t> parent_;
  std::vector<double> length_;
  std::vector<std::vector<std::size_t>> beside_;
  std::span<const double> areas_;
  std::vector<bool> counted_;
  double line_length_;
  double counted_area_ = 0.0;
};

double bounding_diagonal(std::span<const glm::vec3> positions) {
  if (positions.empty()) return 0.0;
  glm::dvec3 low(positions[0]), high(positions[0]);
  for (const glm::vec3& p : positions) {
    low = glm::min(low, glm::dvec3(p));
    high = glm::max(high, glm::dvec3(p));
  }
  return glm::length(high - low);
}

}  // namespace

CreaseProfile measure_creases(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices) {
  return measure_creases(positions, normals, indices, group_by_position(positions));
}

CreaseProfile measure_creases(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices, std::span<const std::uint32_t> group) {
  CreaseProfile profile;
  FlatMap<std::uint64_t, OpenSide, std::hash<std::uint64_t>> sides(indices.size() / 2);
  std::array<double, 181> length_over{};
  double total_length = 0.0;
  std::vector<CreasedEdge> creased;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      std::uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
      if (group[a] == group[b]) continue;
      if (group[a] > group[b]) std::swap(a, b);
      const std::uint64_t key = static_cast<std::uint64_t>(group[a]) << 32 | group[b];
      const auto [side, first] = sides.try_emplace(key, OpenSide{a, b, static_cast<std::uint32_t>(t / 3), false});
      // An edge counts once, with the first two sides met; further sides of
      // a non-manifold edge add nothing.
      if (first || side.matched) continue;
      side.matched = true;
      const double turn =
          std::max(angle_deg(normals[side.at_low], normals[a]), angle_deg(normals[side.at_high], normals[b]));
      const double length = glm::length(glm::dvec3(positions[a]) - glm::dvec3(positions[b]));
      total_length += length;
      if (!(turn > 0.0)) continue;
      // Counted at the largest whole degree it exceeds; summed down below.
      const auto degree = static_cast<std::size_t>(std::min(std::ceil(turn) - 1.0, 180.0));
      length_over[degree] += length;
      creased.push_back({group[a], group[b], length, {side.triangle, t / 3}, degree});
    }
  }
  std::vector<double> areas(indices.size() / 3);
  double total_area = 0.0;
  for (std::size_t tri = 0; tri < areas.size(); ++tri) {
    const glm::dvec3 p0(positions[indices[3 * tri]]), p1(positions[indices[3 * tri + 1]]),
        p2(positions[indices[3 * tri + 2]]);
    areas[tri] = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    total_area += areas[tri];
  }
  // From the sharpest creases down: at angle d every edge turning by more
  // than d is creased, and lines only grow as d falls.
  std::sort(creased.begin(), creased.end(),
            [](const CreasedEdge& x, const CreasedEdge& y) { return x.degree > y.degree; });
  const std::size_t groups = group.empty() ? 0 : *std::max_element(group.begin(), group.end()) + std::size_t{1};
  CreaseLines lines(groups, areas, kCreaseLineLength * bounding_diagonal(positions));
  std::size_t next = 0;
  for (std::size_t d = profile.lines_area_over.size(); d-- > 0;) {
    for (; next < creased.size() && creased[next].degree >= d; ++next) lines.add(creased[next]);
    if (total_area > 0.0) profile.lines_area_over[d] = static_cast<float>(lines.counted_area() / total_area);
  }
  if (total_length > 0.0) {
    double over = 0.0;
    for (std::size_t d = length_over.size(); d-- > 0;) {
      over += length_over[d];
      profile.fraction_over[d] = static_cast<float>(over / total_length);
    }
  }
  return profile;
}

}  // namespace toond::scene
