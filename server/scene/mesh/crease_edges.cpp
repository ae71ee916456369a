#include "scene/mesh/crease_edges.h"

#include <algorithm>
#include <cmath>

#include "scene/mesh/edge_table.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/mesh/model.h"

namespace toond::scene {
namespace {

// The smallest crease angle a request may ask for (the schema's minimum):
// an edge turning by no more than this is creased at no angle.
constexpr int kLeastCreaseDeg = 1;

// What every level's search shares: the points split copies of a vertex
// stand for, and which of them have copies at all.
struct PointGroups {
  std::vector<std::uint32_t> of_vertex;
  std::vector<bool> split;  // per group: more than one vertex lies there
  Bounds bounds;            // of the positions
  double diagonal = 0;      // of that box
};

PointGroups group_points(std::span<const glm::vec3> positions, std::span<const std::uint32_t> position_group) {
  PointGroups groups{{position_group.begin(), position_group.end()}, {}, {}, 0};
  std::vector<std::uint8_t> vertices;
  for (const std::uint32_t g : groups.of_vertex) {
    if (g >= vertices.size()) vertices.resize(g + 1, 0);
    vertices[g] = static_cast<std::uint8_t>(std::min(vertices[g] + 1, 2));
  }
  for (const std::uint8_t count : vertices) groups.split.push_back(count > 1);
  groups.bounds = compute_bounds(positions);
  groups.diagonal = glm::length(glm::dvec3(groups.bounds.max) - glm::dvec3(groups.bounds.min));
  return groups;
}

// One triangle side, from corner k to corner k + 1 of triangle t
// (`corner` = 3t + k), under the key of the edge between its two points.
struct Side {
  std::uint64_t edge;
  std::uint32_t corner;
};

std::uint32_t next_corner(std::uint32_t corner) { return corner - corner % 3 + (corner % 3 + 1) % 3; }
std::uint32_t third_corner(std::uint32_t corner) { return corner - corner % 3 + (corner % 3 + 2) % 3; }

double turn_between_deg(const glm::vec3& a, const glm::vec3& b) {
  const double la = glm::length(glm::dvec3(a)), lb = glm::length(glm::dvec3(b));
  if (!(la > 0.0) || !(lb > 0.0)) return 0.0;
  const double c = std::clamp(glm::dot(glm::dvec3(a), glm::dvec3(b)) / (la * lb), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::acos(-1.0);
}

// An edge found creased at some angle, before the edges are sorted.
struct Found {
  std::uint64_t place = 0;  // its middle's place along a Z-order curve through the mesh's box
  std::uint32_t vertices[4]{};
  int turn = 0;  // whole degrees, rounded up
  double length = 0;
};

// Spreads the low 21 bits of v three apart (bit i to bit 3i).
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

// Where a point lies along a Z-order (Morton) curve through `bounds`:
// points close in space are mostly close along it.
std::uint64_t z_order(const glm::dvec3& p, const Bounds& bounds) {
  std::uint64_t code = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double low = bounds.min[axis], size = bounds.max[axis] - bounds.min[axis];
    const double t = size > 0.0 ? std::clamp((p[axis] - low) / size, 0.0, 1.0) : 0.0;
    code |= spread_bits(static_cast<std::uint64_t>(t * 2097151.0)) << axis;
  }
  return code;
}

// The sides of triangles (not degenerate ones) along edges that may turn:
// an edge turns only where both faces do not share the vertex at one of
// its ends, so at least one end's point is split; elsewhere (a smooth
// mesh, nearly everywhere) nothing is kept to sort.
std::vector<Side> sides_that_may_turn(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                      const PointGroups& groups) {
  std::vector<Side> sides;
  for (std::uint32_t t = 0; t + 2 < indices.size(); t += 3) {
    if (is_degenerate_triangle(glm::dvec3(positions[indices[t]]), glm::dvec3(positions[indices[t + 1]]),
                               glm::dvec3(positions[indices[t + 2]]))) {
      continue;
    }
    for (std::uint32_t corner = t; corner < t + 3; ++corner) {
      const std::uint32_t ga = groups.of_vertex[indices[corner]];
      const std::uint32_t gb = groups.of_vertex[indices[next_corner(corner)]];
      if (ga == gb || (!groups.split[ga] && !groups.split[gb])) continue;
      sides.push_back({EdgeTable::key(ga, gb), corner});
    }
  }
  return sides;
}

// The edge between the sides at corners `first` and `second`, as face 1 and
// face 2, with its turn.
Found pair_sides(std::uint32_t first, std::uint32_t second, std::span<const glm::vec3> positions,
                 std::span<const glm::vec3> normals, std::span<const std::uint32_t> indices,
                 const PointGroups& groups) {
  const std::uint32_t a = indices[first], b = indices[next_corner(first)];
  // Face 2 runs the edge either way round (the other way when wound like face 1).
  std::uint32_t a2 = indices[second], b2 = indices[next_corner(second)];
  if (groups.of_vertex[a2] != groups.of_vertex[a]) std::swap(a2, b2);
  Found edge;
  edge.place = z_order(0.5 * (glm::dvec3(positions[a]) + glm::dvec3(positions[b])), groups.bounds);
  edge.vertices[0] = indices[third_corner(first)];
  edge.vertices[1] = a;
  edge.vertices[2] = b;
  edge.vertices[3] = indices[third_corner(second)];
  const double turn = std::max(turn_between_deg(normals[a], normals[a2]), turn_between_deg(normals[b], normals[b2]));
  edge.turn = static_cast<int>(std::min(std::ceil(turn), 180.0));
  edge.length = glm::length(glm::dvec3(positions[a]) - glm::dvec3(positions[b]));
  return edge;
}

CreaseEdges find_in(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                    std::span<const std::uint32_t> indices, const PointGroups& groups) {
  std::vector<Side> sides = sides_that_may_turn(positions, indices, groups);
  std::sort(sides.begin(), sides.end(),
            [](const Side& l, const Side& r) { return l.edge != r.edge ? l.edge < r.edge : l.corner < r.corner; });
  std::vector<Found> found;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t end = i + 1;
    while (end < sides.size() && sides[end].edge == sides[i].edge) ++end;
    // The first two sides met; further sides of a non-manifold edge add nothing.
    if (end - i >= 2) {
      const Found edge = pair_sides(sides[i].corner, sides[i + 1].corner, positions, normals, indices, groups);
      if (edge.turn > kLeastCreaseDeg) found.push_back(edge);
    }
    i = end;
  }
  // The greatest turn first; within a whole degree, along a Z-order curve,
  // so that edges drawn together lie together and face alike (a run of
  // them whose faces all turn away is skipped, render/cull/facing_runs.h).
  std::sort(found.begin(), found.end(),
            [](const Found& l, const Found& r) { return l.turn != r.turn ? l.turn > r.turn : l.place < r.place; });
  std::vector<int> turns;
  std::vector<double> lengths;
  for (const Found& edge : found) {
    turns.push_back(edge.turn);
    lengths.push_back(edge.length);
  }
  CreaseEdges edges;
  static_cast<TurnTally&>(edges) = tally_turns(turns, lengths, groups.diagonal);
  edges.indices.reserve(found.size() * 4);
  for (const Found& edge : found)
    edges.indices.insert(edges.indices.end(), std::begin(edge.vertices), std::end(edge.vertices));
  return edges;
}

std::size_t whole_degrees(double degrees) {
  return static_cast<std::size_t>(std::clamp(std::floor(degrees), 0.0, 180.0));
}

}  // namespace

std::size_t TurnTally::creased_at(double degrees) const { return edges_over[whole_degrees(degrees)]; }

double TurnTally::length_at(double degrees) const { return length_over[whole_degrees(degrees)]; }

TurnTally tally_turns(std::span<const int> turns, std::span<const double> lengths, double diagonal) {
  std::array<double, 181> length_at_turn{};
  std::array<std::uint32_t, 181> count_at_turn{};
  for (std::size_t i = 0; i < turns.size(); ++i) {
    const auto turn = static_cast<std::size_t>(std::clamp(turns[i], 0, 180));
    length_at_turn[turn] += lengths[i];
    ++count_at_turn[turn];
  }
  // Over d degrees: every line whose turn, rounded up, is above d.
  TurnTally tally;
  double length = 0;
  std::uint32_t count = 0;
  for (std::size_t d = 180; d-- > 0;) {
    length += length_at_turn[d + 1];
    count += count_at_turn[d + 1];
    tally.edges_over[d] = count;
    tally.length_over[d] = diagonal > 0.0 ? static_cast<float>(length / diagonal) : 0.0f;
  }
  return tally;
}

CreaseEdges find_crease_edges(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices) {
  return find_in(positions, normals, indices, group_points(positions, group_by_position(positions)));
}

void find_crease_edges(Mesh& mesh) { find_crease_edges(mesh, group_by_position(mesh.positions)); }

void find_crease_edges(Mesh& mesh, std::span<const std::uint32_t> position_group) {
  const PointGroups groups = group_points(mesh.positions, position_group);
  mesh.crease_edges = find_in(mesh.positions, mesh.normals, mesh.indices, groups);
  for (MeshLod& lod : mesh.lods) lod.crease_edges = find_in(mesh.positions, mesh.normals, lod.indices, groups);
}

}  // namespace toond::scene
