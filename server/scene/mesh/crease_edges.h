#pragma once
// The edges crease lines are drawn along (render/passes/crease_pass.cpp):
// where the shading normals on the two sides of an edge turn by more than
// the request's crease angle. Which edges those are depends on the angle,
// which comes with each request, so import finds every edge that turns at
// all (by more than the smallest crease angle a request may ask for) and
// sorts them by their turn, the greatest first: the edges creased at any
// angle are then the first so many, and a render draws one range of them.
//
// The turn is measured as CreaseProfile measures it (crease_profile.h): the
// larger of the turns at the edge's two ends, between the normals the two
// faces give the same point; split copies of a position count as one
// point. An edge creased at angle θ turns by more than θ's whole degrees
// (CreaseProfile::at reads θ the same way).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace toond::scene {

struct Mesh;

// Lines along which a surface turns (crease edges, and the seams where
// parts cross, scene/mesh/intersection_lines.h), counted by their turn, the
// greatest first.
struct TurnTally {
  // edges_over[d]: how many lines turn by more than d degrees; they are
  // the first edges_over[d] of their list.
  std::array<std::uint32_t, 181> edges_over{};
  // length_over[d]: the length of those lines added up, in units of the
  // mesh's bounding-box diagonal (what the price turns into pixels).
  std::array<float, 181> length_over{};

  // How many lines are creased at a crease angle of `degrees`.
  std::size_t creased_at(double degrees) const;
  // Their length added up, in bounding-box diagonals.
  double length_at(double degrees) const;
};

// The tally of lines sorted greatest turn first, given each one's turn in
// whole degrees rounded up (1..180) and its length, and the diagonal the
// lengths are counted in.
TurnTally tally_turns(std::span<const int> turns, std::span<const double> lengths, double diagonal);

struct CreaseEdges : TurnTally {
  // Four vertex indices per edge, for GL_LINES_ADJACENCY: c1, a, b, c2.
  // Face 1 is (a, b, c1) in its own winding; c2 is the third corner of
  // face 2, which a consistently wound mesh winds (b, a, c2). a and b are
  // face 1's vertices (face 2's copies lie at the same points).
  std::vector<std::uint32_t> indices;

  std::size_t size() const { return indices.size() / 4; }
};

// Every edge between two triangles whose normals turn by more than 1°,
// sorted as above. Positions must be welded (equal where the model means
// one point). An edge counts with the first two triangles met on it (as
// in the crease profile); edges of degenerate triangles are left out
// (their plane, which the pass draws the line along, is undefined).
CreaseEdges find_crease_edges(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices);

// Sets Mesh::crease_edges for the full mesh and every level of detail (a
// level's own triangles meet at its own edges).
void find_crease_edges(Mesh& mesh);
// The same for a caller that has group_by_position(mesh.positions) already.
void find_crease_edges(Mesh& mesh, std::span<const std::uint32_t> position_group);

}  // namespace toond::scene
