#include "scene/mesh/normals_by_angle.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "scene/mesh/mesh_processing.h"
#include "scene/mesh/union_find.h"

namespace toond::scene {
namespace {

// One side of an edge: the edge by its two position classes (smaller
// first), and the triangle's corners at those two positions.
struct EdgeSide {
  std::uint64_t key;
  std::uint32_t corner_at_low;
  std::uint32_t corner_at_high;
};

// Sides ordered by their edge (low class, then high class), stable: two
// counting sorts, by the high class and then by the low one, so the time is
// linear in sides and classes whatever meets at one position (a comparison
// sort's log factor showed in the import's n-versus-2n test).
std::vector<EdgeSide> sorted_by_key(std::vector<EdgeSide> sides, std::size_t classes) {
  std::vector<EdgeSide> out(sides.size());
  std::vector<std::size_t> start(classes + 1);
  for (const int shift : {0, 32}) {
    std::fill(start.begin(), start.end(), 0);
    for (const EdgeSide& side : sides) ++start[((side.key >> shift) & 0xffffffffu) + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    for (const EdgeSide& side : sides) out[start[(side.key >> shift) & 0xffffffffu]++] = side;
    sides.swap(out);
  }
  return sides;
}

}  // namespace

std::vector<std::uint32_t> corner_groups_by_angle(std::span<const glm::vec3> positions,
                                                  std::span<const std::uint32_t> position_class,
                                                  std::span<const std::uint32_t> indices,
                                                  std::span<const std::uint8_t> eligible_corner, double angle_deg) {
  const std::size_t corners = indices.size();
  const std::size_t triangles = corners / 3;
  std::vector<glm::dvec3> face_normal(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    face_normal[t] = triangle_normal(glm::dvec3(positions[indices[3 * t]]), glm::dvec3(positions[indices[3 * t + 1]]),
                                     glm::dvec3(positions[indices[3 * t + 2]]));
  }
  // A face too thin to have a normal (a sliver at a pole whose corners an
  // exporter wrote 1e-16 apart) has no angle to anyone: it is left out of
  // the edges (it would make a fin of its neighbours' edge), and its corners
  // take the group of a face at the same position.
  const auto sliver = [&](std::size_t t) { return glm::dot(face_normal[t], face_normal[t]) < 0.5; };
  std::vector<EdgeSide> sides;
  sides.reserve(corners);
  for (std::size_t t = 0; t < triangles; ++t) {
    if (sliver(t)) continue;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint32_t>(3 * t + k);
      const auto b = static_cast<std::uint32_t>(3 * t + (k + 1) % 3);
      std::uint32_t pa = position_class[indices[a]];
      std::uint32_t pb = position_class[indices[b]];
      if (pa == pb) continue;
      const bool a_low = pa < pb;
      if (!a_low) std::swap(pa, pb);
      sides.push_back({(static_cast<std::uint64_t>(pa) << 32) | pb, a_low ? a : b, a_low ? b : a});
    }
  }
  sides = sorted_by_key(std::move(sides), position_class.size());

  // Strictly less than the angle: at 0 nothing joins, not even coplanar
  // faces whose normals round a hair apart.
  const double cos_limit = std::cos(glm::radians(std::clamp(angle_deg, 0.0, 180.0)));
  UnionFind sets(corners);
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t end = i + 1;
    while (end < sides.size() && sides[end].key == sides[i].key) ++end;
    // An edge of one face is a rim, of three or more a fin: both sharp.
    if (end - i == 2) {
      const EdgeSide& s = sides[i];
      const EdgeSide& o = sides[i + 1];
      const std::size_t ts = s.corner_at_low / 3, to = o.corner_at_low / 3;
      const bool smooth = glm::dot(face_normal[ts], face_normal[to]) > cos_limit && angle_deg > 0;
      if (smooth) {
        if (eligible_corner[s.corner_at_low] && eligible_corner[o.corner_at_low]) {
          sets.join(s.corner_at_low, o.corner_at_low);
        }
        if (eligible_corner[s.corner_at_high] && eligible_corner[o.corner_at_high]) {
          sets.join(s.corner_at_high, o.corner_at_high);
        }
      }
    }
    i = end;
  }

  std::vector<std::uint32_t> face_at(position_class.size(), ~0u);  // by position class: a real face's corner
  for (std::uint32_t c = 0; c < corners; ++c) {
    if (eligible_corner[c] && !sliver(c / 3) && face_at[position_class[indices[c]]] == ~0u) {
      face_at[position_class[indices[c]]] = c;
    }
  }
  for (std::uint32_t c = 0; c < corners; ++c) {
    const std::uint32_t other = face_at[position_class[indices[c]]];
    if (eligible_corner[c] && sliver(c / 3) && other != ~0u) sets.join(c, other);
  }

  std::vector<std::uint32_t> group(corners);
  std::vector<std::uint32_t> dense(corners, ~0u);
  std::uint32_t next = 0;
  for (std::uint32_t c = 0; c < corners; ++c) {
    const std::uint32_t root = sets.root(c);
    if (dense[root] == ~0u) dense[root] = next++;
    group[c] = dense[root];
  }
  return group;
}

}  // namespace toond::scene
