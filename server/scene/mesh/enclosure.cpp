#include "scene/mesh/enclosure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "scene/mesh/edge_table.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/mesh/union_find.h"

namespace toond::scene {
namespace {

// Per edge between two groups (smaller id in the high half): how many more
// times the triangles cross it from the smaller id to the larger than back.
EdgeTable edge_balance(std::span<const std::uint32_t> group, std::span<const std::uint32_t> indices) {
  EdgeTable balance(indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = group[indices[t + k]];
      const std::uint32_t b = group[indices[t + (k + 1) % 3]];
      if (a == b) continue;  // a collapsed corner: no edge
      balance[EdgeTable::key(a, b)] += a < b ? 1 : -1;
    }
  }
  return balance;
}

// The rims of the holes, as loops of groups in the direction the mesh's own
// triangles run along them. False when a rim edge is crossed more than once
// unmatched, or rims touch (two rim edges leave one point): no unique caps.
bool trace_rims(const EdgeTable& balance, std::vector<std::vector<std::uint32_t>>& rims) {
  std::unordered_map<std::uint32_t, std::uint32_t> next;
  bool unique = true;
  balance.for_each([&](std::uint64_t key, int b) {
    if (b == 0 || !unique) return;
    if (b != 1 && b != -1) {
      unique = false;
      return;
    }
    const auto low = static_cast<std::uint32_t>(key >> 32);
    const auto high = static_cast<std::uint32_t>(key & 0xffffffffu);
    const auto [from, to] = b > 0 ? std::pair(low, high) : std::pair(high, low);
    if (!next.emplace(from, to).second) unique = false;
  });
  if (!unique) return false;
  while (!next.empty()) {
    std::vector<std::uint32_t> rim;
    std::uint32_t at = next.begin()->first;
    while (true) {
      const auto it = next.find(at);
      if (it == next.end()) break;
      rim.push_back(at);
      at = it->second;
      next.erase(it);
    }
    // A rim must come back to where it started.
    if (rim.empty() || at != rim.front()) return false;
    rims.push_back(std::move(rim));
  }
  return true;
}

// Capping costs rim length cubed: a long rim (an open sheet's border) or
// many of them (a hostile upload) leave the mesh Open instead, which only
// means its back faces are drawn.
constexpr std::size_t kLongestRim = 256;
constexpr double kCappingBudget = 4e7;  // Σ n³ over the rims: a fraction of a second, not minutes

// Whether the holes surely cannot be capped: a rim longer than kLongestRim,
// or rims over the capping budget. The rims' lengths do not depend on where
// each is entered, so they are found here over flat arrays, each loop
// walked once; trace_rims, whose order the caps follow, then runs only
// where capping may succeed. False also where the rim edges do not close
// into separate loops (trace_rims refuses those).
bool rims_surely_too_long(const EdgeTable& balance, std::size_t groups) {
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> rim_edges;  // from, to
  bool unique = true;
  balance.for_each([&](std::uint64_t key, int b) {
    if (b == 0) return;
    if (b != 1 && b != -1) unique = false;
    const auto low = static_cast<std::uint32_t>(key >> 32);
    const auto high = static_cast<std::uint32_t>(key & 0xffffffffu);
    rim_edges.push_back(b > 0 ? std::pair(low, high) : std::pair(high, low));
  });
  if (!unique || rim_edges.empty()) return false;
  std::vector<std::uint32_t> next(groups, kNone);
  for (const auto& [from, to] : rim_edges) {
    if (next[from] != kNone) return false;
    next[from] = to;
  }
  double capping = 0;
  for (const auto& [start, first_step] : rim_edges) {
    if (next[start] == kNone) continue;  // on a loop walked already
    std::size_t length = 0;
    std::uint32_t at = start;
    while (next[at] != kNone) {
      const std::uint32_t to = next[at];
      next[at] = kNone;
      at = to;
      ++length;
    }
    if (at != start) return false;
    if (length > kLongestRim) return true;
    capping += std::pow(static_cast<double>(length), 3.0);
  }
  return capping > kCappingBudget;
}

// The triangulation of least total area spanning the loop of points (dynamic
// programming over its vertices, O(n³)), its triangles wound like the loop.
// A fan from the middle would do for round holes, but scanned models (the
// bunny's base) have ragged, saddle-shaped rims whose fan or ear-clipped
// triangles fold over each other and face every way; the least-area
// surface is the soap film over the rim, and stays as flat as the rim
// lets it. False for rims too long to be worth it.
bool triangulate_hole(const std::vector<std::uint32_t>& loop, const std::vector<glm::dvec3>& point,
                      std::vector<std::array<std::uint32_t, 3>>& out) {
  const std::size_t n = loop.size();
  if (n < 3 || n > kLongestRim) return false;
  auto area = [&](std::size_t i, std::size_t k, std::size_t j) {
    const glm::dvec3& a = point[loop[i]];
    return glm::length(glm::cross(point[loop[k]] - a, point[loop[j]] - a));
  };
  // best[i][j]: least area closing the sub-loop i..j; split[i][j]: its apex.
  std::vector<double> best(n * n, 0.0);
  std::vector<std::size_t> split(n * n, 0);
  for (std::size_t span = 2; span < n; ++span) {
    for (std::size_t i = 0; i + span < n; ++i) {
      const std::size_t j = i + span;
      double least = std::numeric_limits<double>::infinity();
      for (std::size_t k = i + 1; k < j; ++k) {
        const double a = best[i * n + k] + best[k * n + j] + area(i, k, j);
        if (a < least) {
          least = a;
          split[i * n + j] = k;
        }
      }
      best[i * n + j] = least;
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> todo = {{0, n - 1}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (j < i + 2) continue;
    const std::size_t k = split[i * n + j];
    out.push_back({loop[i], loop[k], loop[j]});
    todo.emplace_back(i, k);
    todo.emplace_back(k, j);
  }
  return true;
}

struct Part {
  double volume = 0;  // signed: positive when counter-clockwise faces look out
  glm::dvec3 min{std::numeric_limits<double>::max()};
  glm::dvec3 max{std::numeric_limits<double>::lowest()};
  void add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    // The divergence theorem: the tetrahedra the triangles make with the origin.
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    for (const glm::dvec3& p : {a, b, c}) {
      min = glm::min(min, p);
      max = glm::max(max, p);
    }
  }
};

}  // namespace

Enclosure classify_enclosure(std::span<const glm::vec3> positions, std::span<const std::uint32_t> position_group,
                             std::span<const std::uint32_t> indices, std::vector<glm::vec3>* caps,
                             std::vector<std::uint32_t>* cap_indices) {
  if (caps) caps->clear();
  if (cap_indices) cap_indices->clear();
  if (indices.size() < 3) return Enclosure::Open;
  const std::size_t groups =
      position_group.empty() ? 0 : *std::max_element(position_group.begin(), position_group.end()) + 1u;
  const EdgeTable balance = edge_balance(position_group, indices);
  if (rims_surely_too_long(balance, groups)) return Enclosure::Open;
  std::vector<std::vector<std::uint32_t>> rims;
  if (!trace_rims(balance, rims)) return Enclosure::Open;
  if (!rims.empty() && !caps) return Enclosure::Open;
  double capping = 0;
  for (const std::vector<std::uint32_t>& rim : rims) capping += std::pow(static_cast<double>(rim.size()), 3.0);
  if (capping > kCappingBudget) return Enclosure::Open;

  std::vector<glm::dvec3> point(groups);
  std::vector<std::uint32_t> vertex_of(groups);  // one vertex at each point: the caps draw with the mesh's
  for (std::size_t v = 0; v < positions.size(); ++v) {
    point[position_group[v]] = glm::dvec3(positions[v]);
    vertex_of[position_group[v]] = static_cast<std::uint32_t>(v);
  }
  UnionFind components(groups);  // which triangles hang together
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    components.join(position_group[indices[t]], position_group[indices[t + 1]]);
    components.join(position_group[indices[t]], position_group[indices[t + 2]]);
  }
  std::unordered_map<std::uint32_t, Part> parts;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    parts[components.root(position_group[indices[t]])].add(point[position_group[indices[t]]],
                                                           point[position_group[indices[t + 1]]],
                                                           point[position_group[indices[t + 2]]]);
  }
  // Each hole closed by a triangulation of its rim, run against the rim so
  // the cap continues the mesh's winding.
  for (const std::vector<std::uint32_t>& rim : rims) {
    std::vector<std::uint32_t> loop(rim.rbegin(), rim.rend());
    std::vector<std::array<std::uint32_t, 3>> triangles;
    if (!triangulate_hole(loop, point, triangles)) {
      caps->clear();
      if (cap_indices) cap_indices->clear();
      return Enclosure::Open;
    }
    Part& part = parts[components.root(rim.front())];
    for (const auto& [a, b, c] : triangles) {
      part.add(point[a], point[b], point[c]);
      caps->insert(caps->end(), {glm::vec3(point[a]), glm::vec3(point[b]), glm::vec3(point[c])});
      if (cap_indices) cap_indices->insert(cap_indices->end(), {vertex_of[a], vertex_of[b], vertex_of[c]});
    }
  }
  int outward = 0;
  int inward = 0;
  for (const auto& [root, part] : parts) {
    // Against the cube of its own size, so a small part counts as much as a
    // large one; what stays under this is a flat or two-sided sheet.
    const double size = glm::length(part.max - part.min);
    const double least = 1e-7 * size * size * size;
    if (part.volume > least)
      ++outward;
    else if (part.volume < -least)
      ++inward;
    else
      outward = inward = 1;  // no side to skip
  }
  if (inward == 0 && outward > 0) return Enclosure::Outward;
  if (outward == 0 && inward > 0) return Enclosure::Inward;
  if (caps) caps->clear();
  if (cap_indices) cap_indices->clear();
  return Enclosure::Open;
}

void classify_enclosures(Mesh& mesh) { classify_enclosures(mesh, group_by_position(mesh.positions)); }

void classify_enclosures(Mesh& mesh, std::span<const std::uint32_t> group) {
  mesh.enclosure = classify_enclosure(mesh.positions, group, mesh.indices, &mesh.caps, &mesh.cap_indices);
  for (MeshLod& lod : mesh.lods) {
    lod.enclosure = classify_enclosure(mesh.positions, group, lod.indices, &lod.caps, &lod.cap_indices);
  }
}

}  // namespace toond::scene
