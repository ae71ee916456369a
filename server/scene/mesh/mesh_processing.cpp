#include "scene/mesh/mesh_processing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "scene/mesh/edge_table.h"

namespace toond::scene {
namespace {

constexpr std::uint32_t kNoGroup = ~0u;

// Longest outline offset, in units of the outline width.
constexpr double kMaxMitre = 3.0;

// Relative to the squared longest edge: below this the cross product is
// rounding noise and the face normal would point anywhere.
constexpr double kDegenerateRatio = 1e-10;

struct PositionKey {
  std::array<std::uint32_t, 3> bits;
  bool operator==(const PositionKey&) const = default;
};

PositionKey key_of(const glm::vec3& p) {
  PositionKey key{};
  for (int i = 0; i < 3; ++i) {
    const float value = p[i] + 0.0f;  // folds -0 into +0
    std::memcpy(&key.bits[static_cast<std::size_t>(i)], &value, sizeof value);
  }
  return key;
}

// FNV-1a over the three words, then Fibonacci hashing: the table's index
// is taken from the top bits, which the multiply mixes best.
std::uint64_t hash_of(const PositionKey& k) {
  std::uint64_t h = 1469598103934665603ull;
  for (const auto b : k.bits) h = (h ^ b) * 1099511628211ull;
  return h * 0x9E3779B97F4A7C15ull;
}

glm::vec3 to_unit_float(const glm::dvec3& v) {
  const double len = glm::length(v);
  if (!(len > 0.0) || !std::isfinite(len)) return glm::vec3(0.0f);
  return glm::vec3(v / len);
}

}  // namespace

bool is_degenerate_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double longest = std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
  if (!(longest > 0.0) || !std::isfinite(longest)) return true;
  const double doubled_area = glm::length(glm::cross(b - a, c - a));
  return !(doubled_area > kDegenerateRatio * longest);
}

glm::dvec3 triangle_normal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  return len > 0.0 && std::isfinite(len) ? n / len : glm::dvec3(0.0);
}

glm::dvec3 triangle_angles(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  // atan2 of |cross| and dot stays accurate for angles near 0 and pi, where
  // acos of a normalised dot product loses most of its digits.
  const auto angle = [](const glm::dvec3& u, const glm::dvec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
  };
  return {angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)};
}

namespace {

// Calls fn(corner indices, corner positions, unit normal, corner angles) for
// every triangle with an area; degenerate ones have no normal to give.
template <class Fn>
void for_each_shaded_triangle(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices, Fn&& fn) {
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t i[3] = {indices[t], indices[t + 1], indices[t + 2]};
    const glm::dvec3 p[3] = {positions[i[0]], positions[i[1]], positions[i[2]]};
    const glm::dvec3 n = triangle_normal(p[0], p[1], p[2]);
    if (n == glm::dvec3(0.0)) continue;
    fn(i, p, n, triangle_angles(p[0], p[1], p[2]));
  }
}

// A triangle with an area: its corners (vertex ids), unit normal and
// corner angles.
struct ShadedTriangle {
  std::uint32_t corner[3];
  glm::dvec3 normal;
  glm::dvec3 angles;
};

std::vector<ShadedTriangle> shaded_triangles(std::span<const glm::vec3> positions,
                                             std::span<const std::uint32_t> indices) {
  std::vector<ShadedTriangle> shaded;
  shaded.reserve(indices.size() / 3);
  for_each_shaded_triangle(
      positions, indices,
      [&](const std::uint32_t(&i)[3], const glm::dvec3(&)[3], const glm::dvec3& n, const glm::dvec3& angles) {
        shaded.push_back({{i[0], i[1], i[2]}, n, angles});
      });
  return shaded;
}

}  // namespace

std::vector<std::uint32_t> group_by_position(std::span<const glm::vec3> positions) {
  // Open addressing in one flat array sized once, each slot the first
  // vertex at a point: an import asks for the groups of every vertex, and a
  // node per point (a std::unordered_map) cost an allocation each and
  // scattered the points over the heap. A slot of four bytes keeps the
  // table in cache where a copy of the key beside it would not.
  int bits = 4;
  while ((std::size_t{1} << bits) < 2 * positions.size()) ++bits;
  std::vector<std::uint32_t> slots(std::size_t{1} << bits, kNoGroup);  // the first vertex at a point
  const std::size_t mask = slots.size() - 1;
  std::vector<std::uint32_t> groups(positions.size());
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const PositionKey key = key_of(positions[v]);
    std::size_t i = static_cast<std::size_t>(hash_of(key) >> (64 - bits));
    while (slots[i] != kNoGroup && !(key_of(positions[slots[i]]) == key)) i = (i + 1) & mask;
    if (slots[i] == kNoGroup) {
      slots[i] = static_cast<std::uint32_t>(v);
      groups[v] = next++;
    } else {
      groups[v] = groups[slots[i]];
    }
  }
  return groups;
}

std::vector<glm::vec3> compute_grouped_normals(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               std::span<const std::uint32_t> group_of_vertex,
                                               std::span<const glm::vec3> fallback) {
  const std::uint32_t group_count =
      group_of_vertex.empty() ? 0u : *std::max_element(group_of_vertex.begin(), group_of_vertex.end()) + 1u;
  std::vector<glm::dvec3> sums(group_count, glm::dvec3(0.0));
  std::vector<glm::dvec3> first_face(positions.size(), glm::dvec3(0.0));

  for_each_shaded_triangle(
      positions, indices,
      [&](const std::uint32_t(&i)[3], const glm::dvec3(&)[3], const glm::dvec3& n, const glm::dvec3& angles) {
        for (int k = 0; k < 3; ++k) {
          sums[group_of_vertex[i[k]]] += n * angles[k];
          if (first_face[i[k]] == glm::dvec3(0.0)) first_face[i[k]] = n;
        }
      });

  std::vector<glm::vec3> normals(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    glm::vec3 n = to_unit_float(sums[group_of_vertex[v]]);
    if (n == glm::vec3(0.0f) && v < fallback.size()) n = to_unit_float(glm::dvec3(fallback[v]));
    if (n == glm::vec3(0.0f)) n = to_unit_float(first_face[v]);
    if (n == glm::vec3(0.0f)) n = glm::vec3(0.0f, 1.0f, 0.0f);
    normals[v] = n;
  }
  return normals;
}

std::vector<glm::vec3> compute_angle_weighted_normals(std::span<const glm::vec3> positions,
                                                      std::span<const std::uint32_t> indices) {
  std::vector<std::uint32_t> own(positions.size());
  for (std::size_t v = 0; v < own.size(); ++v) own[v] = static_cast<std::uint32_t>(v);
  return compute_grouped_normals(positions, indices, own);
}

std::vector<glm::vec3> compute_outline_normals(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               std::span<const glm::vec3> shading_normals) {
  return compute_outline_normals(positions, indices, shading_normals, group_by_position(positions));
}

namespace {

// How many triangles use each edge between position groups.
EdgeTable edge_uses(std::span<const std::uint32_t> indices, std::span<const std::uint32_t> groups) {
  EdgeTable uses(indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      ++uses[EdgeTable::key(groups[indices[t + k]], groups[indices[t + (k + 1) % 3]])];
    }
  }
  return uses;
}

// A few distinct face directions per position group, to tell a real rim
// from an edge that only looks open: at a T-junction (one face splits an
// edge its neighbour does not) the edge is used once, but the neighbour's
// face already pushes the way the rim would. Counting both tilted a
// corner's offset off its faces and its mitre out to three widths. Each is
// kept as the triangle whose normal it is.
class FaceDirections {
 public:
  FaceDirections(std::span<const ShadedTriangle> shaded, std::span<const std::uint32_t> groups, std::size_t group_count)
      : shaded_(shaded), kept_(group_count * kKept), known_(group_count, 0) {
    for (std::uint32_t s = 0; s < shaded.size(); ++s) {
      for (const std::uint32_t corner : shaded[s].corner) add(groups[corner], s);
    }
  }

  // Whether a face of `group` already pushes roughly along `direction`.
  bool push_that_way(std::uint32_t group, const glm::dvec3& direction) const {
    const auto dirs = of(group);
    return std::any_of(dirs.begin(), dirs.end(),
                       [&](std::uint32_t d) { return glm::dot(shaded_[d].normal, direction) > 0.7; });
  }

 private:
  static constexpr std::size_t kKept = 8;

  std::span<const std::uint32_t> of(std::uint32_t group) const {
    return std::span(&kept_[group * kKept], known_[group]);
  }

  void add(std::uint32_t group, std::uint32_t triangle) {
    const glm::dvec3& n = shaded_[triangle].normal;
    const auto dirs = of(group);
    const bool known =
        std::any_of(dirs.begin(), dirs.end(), [&](std::uint32_t d) { return glm::dot(shaded_[d].normal, n) > 0.999; });
    if (!known && known_[group] < kKept) kept_[group * kKept + known_[group]++] = triangle;
  }

  std::span<const ShadedTriangle> shaded_;
  std::vector<std::uint32_t> kept_;
  std::vector<std::uint8_t> known_;
};

struct RimPush {
  std::uint32_t group;
  glm::dvec3 outward;
};

// On an open rim (a leg without a sole, a flat eye decal) the hull must also
// move outward in the face's plane across the boundary edge, as if a cap
// closed the hole; without it an open mesh gets no outline past its
// boundary. Edges that only look open (FaceDirections) push nothing more.
std::vector<RimPush> rim_pushes(std::span<const glm::vec3> positions, std::span<const ShadedTriangle> shaded,
                                std::span<const std::uint32_t> groups, const EdgeTable& edge_use,
                                const FaceDirections& directions) {
  std::vector<RimPush> pushes;
  for (const ShadedTriangle& tri : shaded) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri.corner[k], b = tri.corner[(k + 1) % 3];
      if (edge_use.get(EdgeTable::key(groups[a], groups[b])) != 1) continue;
      // In the face's plane, perpendicular to the edge, away from the
      // triangle (counter-clockwise winding puts the interior on the left).
      const glm::dvec3 outward =
          glm::normalize(glm::cross(glm::dvec3(positions[b]) - glm::dvec3(positions[a]), tri.normal));
      for (const std::uint32_t g : {groups[a], groups[b]}) {
        if (!directions.push_that_way(g, outward)) pushes.push_back({g, outward});
      }
    }
  }
  return pushes;
}

// Calls push(group, direction, weight) for every direction a position's
// hull must move away from: its faces' normals (by corner angle) and its
// rim pushes (a quarter turn each). Visited twice (once to sum, once for
// the mitre against the sum) rather than stored per position: a list per
// position cost an allocation each, and more than the rest.
template <class Push>
void for_each_push(std::span<const ShadedTriangle> shaded, std::span<const std::uint32_t> groups,
                   std::span<const RimPush> rims, Push&& push) {
  for (const ShadedTriangle& tri : shaded) {
    for (int k = 0; k < 3; ++k) push(groups[tri.corner[k]], tri.normal, tri.angles[k]);
  }
  const double quarter_turn = std::acos(0.0);
  for (const RimPush& rim : rims) push(rim.group, rim.outward, quarter_turn);
}

// Each group's offset: the unit sum of its pushes, mitred. At a hard corner
// the averaged normal leans away from each face (a cube corner's diagonal
// meets every face at 54.7°), so one unit along it moves each face plane
// by only cos(angle) and the outline comes out thin along edges. Lengthen
// it by 1/min cos, so every face plane moves out one full unit. A face
// turned away (a fold, a two-sided sheet) has no mitre that would help;
// knife edges would need an unbounded one, so past kMaxMitre the corner is
// bevelled instead. Zero where the faces cancel.
std::vector<glm::dvec3> mitred_group_offsets(std::span<const ShadedTriangle> shaded,
                                             std::span<const std::uint32_t> groups, std::span<const RimPush> rims,
                                             std::size_t group_count) {
  std::vector<glm::dvec3> sums(group_count, glm::dvec3(0.0));
  for_each_push(shaded, groups, rims,
                [&](std::uint32_t g, const glm::dvec3& direction, double weight) { sums[g] += direction * weight; });
  std::vector<glm::dvec3> units(group_count, glm::dvec3(0.0));
  for (std::size_t g = 0; g < group_count; ++g) {
    const double length = glm::length(sums[g]);
    if (length > 1e-12) units[g] = sums[g] / length;
  }
  std::vector<double> min_cos(group_count, 1.0);
  for_each_push(shaded, groups, rims, [&](std::uint32_t g, const glm::dvec3& direction, double) {
    min_cos[g] = std::min(min_cos[g], glm::dot(units[g], direction));
  });
  std::vector<glm::dvec3> offsets(group_count, glm::dvec3(0.0));
  for (std::size_t g = 0; g < group_count; ++g) {
    const double mitre = min_cos[g] <= 0.0 ? 1.0 : 1.0 / std::max(min_cos[g], 1.0 / kMaxMitre);
    offsets[g] = units[g] * mitre;
  }
  return offsets;
}

}  // namespace

std::vector<glm::vec3> compute_outline_normals(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               std::span<const glm::vec3> shading_normals,
                                               std::span<const std::uint32_t> groups) {
  const std::size_t group_count = groups.empty() ? 0 : *std::max_element(groups.begin(), groups.end()) + 1u;
  // Every triangle with an area, its normal and corner angles found once:
  // the pushes are visited twice and the face directions once, and the
  // angles' arc tangents were most of the time.
  const std::vector<ShadedTriangle> shaded = shaded_triangles(positions, indices);
  const FaceDirections directions(shaded, groups, group_count);
  const std::vector<RimPush> rims = rim_pushes(positions, shaded, groups, edge_uses(indices, groups), directions);
  const std::vector<glm::dvec3> group_offset = mitred_group_offsets(shaded, groups, rims, group_count);
  std::vector<glm::vec3> offsets(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    glm::vec3 o(group_offset[groups[v]]);
    if (o == glm::vec3(0.0f) && v < shading_normals.size()) o = to_unit_float(glm::dvec3(shading_normals[v]));
    if (o == glm::vec3(0.0f)) o = glm::vec3(0.0f, 1.0f, 0.0f);
    offsets[v] = o;
  }
  return offsets;
}

glm::vec3 any_perpendicular(const glm::vec3& n_in) {
  glm::dvec3 n(n_in);
  const double len = glm::length(n);
  n = len > 0.0 && std::isfinite(len) ? n / len : glm::dvec3(0.0, 1.0, 0.0);
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  return to_unit_float(glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x));
}

std::vector<glm::vec4> compute_tangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> texcoords, std::span<const std::uint32_t> indices) {
  // Made at the first triangle that gives a direction: a mesh without
  // texture coordinates (all zero) gives none, and skips its triangles'
  // normals and corner angles as well.
  std::vector<glm::dvec3> tangent_sum;
  std::vector<glm::dvec3> bitangent_sum;
  for (std::size_t c = 0; texcoords.size() >= positions.size() && c + 2 < indices.size(); c += 3) {
    const std::uint32_t i[3] = {indices[c], indices[c + 1], indices[c + 2]};
    const glm::dvec2 uv[3] = {texcoords[i[0]], texcoords[i[1]], texcoords[i[2]]};
    const glm::dvec2 d1 = uv[1] - uv[0];
    const glm::dvec2 d2 = uv[2] - uv[0];
    const glm::dvec2 d3 = uv[2] - uv[1];
    // Twice the signed UV area; against the longest UV edge, as for
    // positions, so the test does not depend on the texture's scale.
    const double r = d1.x * d2.y - d2.x * d1.y;
    const double longest = std::max({glm::dot(d1, d1), glm::dot(d2, d2), glm::dot(d3, d3)});
    if (!(std::abs(r) > kDegenerateRatio * longest) || !std::isfinite(r)) continue;
    const glm::dvec3 p[3] = {positions[i[0]], positions[i[1]], positions[i[2]]};
    if (triangle_normal(p[0], p[1], p[2]) == glm::dvec3(0.0)) continue;  // no area to shade
    const glm::dvec3 e1 = p[1] - p[0];
    const glm::dvec3 e2 = p[2] - p[0];
    const glm::dvec3 t = glm::dvec3(to_unit_float((e1 * d2.y - e2 * d1.y) / r));
    const glm::dvec3 b = glm::dvec3(to_unit_float((e2 * d1.x - e1 * d2.x) / r));
    if (t == glm::dvec3(0.0) || b == glm::dvec3(0.0)) continue;
    if (tangent_sum.empty()) {
      tangent_sum.assign(positions.size(), glm::dvec3(0.0));
      bitangent_sum.assign(positions.size(), glm::dvec3(0.0));
    }
    const glm::dvec3 angles = triangle_angles(p[0], p[1], p[2]);
    for (int k = 0; k < 3; ++k) {
      tangent_sum[i[k]] += t * angles[k];
      bitangent_sum[i[k]] += b * angles[k];
    }
  }

  std::vector<glm::vec4> tangents(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    glm::dvec3 n = v < normals.size() ? glm::dvec3(to_unit_float(glm::dvec3(normals[v]))) : glm::dvec3(0.0);
    if (n == glm::dvec3(0.0)) n = glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 sum = tangent_sum.empty() ? glm::dvec3(0.0) : tangent_sum[v];
    const glm::dvec3 t = sum - n * glm::dot(n, sum);
    const double len = glm::length(t);
    // Nearly along the normal, what is left after Gram-Schmidt is noise.
    if (len > 1e-6 * glm::length(sum) && len > 0.0 && std::isfinite(len)) {
      const glm::dvec3 unit = t / len;
      const double w = glm::dot(glm::cross(n, unit), bitangent_sum[v]) < 0.0 ? -1.0 : 1.0;
      const glm::vec3 tf = to_unit_float(unit);
      if (tf != glm::vec3(0.0f)) {
        tangents[v] = glm::vec4(tf, static_cast<float>(w));
        continue;
      }
    }
    tangents[v] = glm::vec4(any_perpendicular(glm::vec3(n)), 1.0f);
  }
  return tangents;
}

Bounds compute_bounds(std::span<const glm::vec3> positions) {
  if (positions.empty()) return {};
  Bounds b{positions.front(), positions.front()};
  for (const auto& p : positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

}  // namespace toond::scene
