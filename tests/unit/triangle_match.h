#pragma once
// Comparing the triangles of two imports of the same geometry whose vertex
// and triangle order may differ (a compressed file and its plain twin):
// each triangle of one must have a triangle of the other at the same place,
// wound the same way, whichever corner it starts from.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/model.h"

namespace toond::scene::test_checks {

using Triangle = std::array<glm::dvec3, 3>;

inline std::vector<Triangle> world_triangles(const Model& m) {
  std::vector<Triangle> out;
  for (std::size_t i = 0; i + 2 < m.mesh.indices.size(); i += 3) {
    Triangle t;
    for (std::size_t k = 0; k < 3; ++k) t[k] = m.mesh.origin + glm::dvec3(m.mesh.positions[m.mesh.indices[i + k]]);
    out.push_back(t);
  }
  return out;
}

// How many triangles of `b` have no triangle of `a` whose corners are each
// within `tolerance` of theirs (same winding, any starting corner).
inline std::size_t unmatched_triangles(const Model& a, const Model& b, double tolerance) {
  const auto centre_x = [](const Triangle& t) { return (t[0].x + t[1].x + t[2].x) / 3.0; };
  std::vector<Triangle> candidates = world_triangles(a);
  std::sort(candidates.begin(), candidates.end(),
            [&](const Triangle& l, const Triangle& r) { return centre_x(l) < centre_x(r); });
  const auto close = [&](const Triangle& l, const Triangle& r) {
    for (std::size_t turn = 0; turn < 3; ++turn) {
      bool all = true;
      for (std::size_t k = 0; k < 3 && all; ++k) all = glm::distance(l[k], r[(k + turn) % 3]) <= tolerance;
      if (all) return true;
    }
    return false;
  };
  std::size_t unmatched = 0;
  for (const Triangle& t : world_triangles(b)) {
    const double x = centre_x(t);
    // The centre's rounding depends on which corner comes first.
    const double window = tolerance + 1e-12 * (1.0 + std::abs(x));
    auto it = std::lower_bound(candidates.begin(), candidates.end(), x - window,
                               [&](const Triangle& c, double v) { return centre_x(c) < v; });
    bool found = false;
    for (; it != candidates.end() && centre_x(*it) <= x + window && !found; ++it) found = close(*it, t);
    if (!found) ++unmatched;
  }
  return unmatched;
}

}  // namespace toond::scene::test_checks
