#pragma once
// Pure geometry helpers used by the importer, kept apart from OBJ parsing so
// they can be tested on hand-made meshes.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/model.h"

namespace toond::scene {

// True when the triangle has no area worth shading: its doubled area is zero
// or negligible against its longest edge (collinear or repeated corners).
bool is_degenerate_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Unit normal of a triangle wound counter-clockwise; zero when degenerate.
glm::dvec3 triangle_normal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Interior angles (radians) at a, b and c.
glm::dvec3 triangle_angles(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Labels vertices with identical coordinates (after -0 == +0) with the same
// dense id, numbered in order of first appearance.
std::vector<std::uint32_t> group_by_position(std::span<const glm::vec3> positions);

// For every vertex, the normalised sum of angle-weighted face normals of all
// triangles that touch any vertex of the same group. Where that sum vanishes
// (a vertex between opposite faces) `fallback[v]` is used when given,
// otherwise the normal of the first face touching the vertex, otherwise +Y.
std::vector<glm::vec3> compute_grouped_normals(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               std::span<const std::uint32_t> group_of_vertex,
                                               std::span<const glm::vec3> fallback = {});

// Smooth shading normals: each vertex gets the angle-weighted average of the
// faces that use it (by index; split vertices stay split).
std::vector<glm::vec3> compute_angle_weighted_normals(std::span<const glm::vec3> positions,
                                                      std::span<const std::uint32_t> indices);

// Offsets for extruding an outline hull, per unit of outline width: the
// normal averaged over every vertex at the same position (so copies split at
// hard edges or UV seams move together and the hull stays closed), mitred
// longer at hard corners so that every face plane moves out a full unit
// (capped at 3 units). Unit length on smooth surfaces. Open boundaries push
// outward across the rim as if capped, so open meshes are outlined there too.
// `shading_normals` is the fallback where faces cancel.
std::vector<glm::vec3> compute_outline_normals(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               std::span<const glm::vec3> shading_normals);
// The same for a caller that has group_by_position(positions) already.
std::vector<glm::vec3> compute_outline_normals(std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> indices,
                                               std::span<const glm::vec3> shading_normals,
                                               std::span<const std::uint32_t> groups);

// Some unit vector perpendicular to `n` (normalised first; +Y when it has no
// direction), continuous in n everywhere but near -Z (the branch-free
// construction from the sign of n.z).
glm::vec3 any_perpendicular(const glm::vec3& n);

// Per-vertex tangents for normal mapping (see Mesh::tangents). Every
// triangle with a positional and a UV area gives the directions of dP/dU and
// dP/dV (the standard per-triangle derivation from its edges and UV
// deltas); they are summed per vertex weighted by the corner angle, the
// tangent sum is made orthogonal to the vertex's normal (Gram-Schmidt), and
// w is -1 where the summed dP/dV points against cross(normal, tangent)
// (mirrored UVs). Vertices that get no usable direction (UVs missing or
// degenerate, or dP/dU along the normal) get any_perpendicular(normal),
// w = +1. `normals` and `texcoords` are per vertex like `positions`.
std::vector<glm::vec4> compute_tangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> texcoords, std::span<const std::uint32_t> indices);

Bounds compute_bounds(std::span<const glm::vec3> positions);

}  // namespace toond::scene
