#pragma once
// Normals by angle, for files that give none: faces meeting at a sharp
// edge keep their own normals there, faces meeting at a shallow one share a
// smoothed normal, as Blender's Auto Smooth, MeshLab and trimesh shade such
// files. Smoothing every edge (what toond did) rounds a machined part's
// flat faces into ragged bands and hides the creases its line passes look
// for; smoothing none faces a sphere.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace toond::scene {

// The default upload's angle (degrees), as Blender's Auto Smooth.
inline constexpr double kDefaultSmoothAngle = 30.0;
// Flat shading that still shares the corners of faces lying in one plane
// (the two triangles of a quad): any turn between faces splits them.
inline constexpr double kFlatSmoothAngle = 0.01;

// Per corner (an entry of `indices`), a group id: two corners at one
// position share a group when their triangles are joined through a chain
// of smooth edges around that position. An edge is smooth when exactly two
// triangles share it (by `position_class`, welded positions counting as
// one) and their normals turn by less than `angle_deg`. The corners of a
// face too thin to have a normal join a face's at their position. At 0 no edge is
// smooth (flat shading), at 180 every two-sided edge is. Corners whose
// `eligible` is false (their vertex brought its own normal, or smoothing
// groups decide) join no group but their own. Group ids are dense, from 0.
// Linear in the triangles and positions, whatever meets at one position.
std::vector<std::uint32_t> corner_groups_by_angle(std::span<const glm::vec3> positions,
                                                  std::span<const std::uint32_t> position_class,
                                                  std::span<const std::uint32_t> indices,
                                                  std::span<const std::uint8_t> eligible_corner, double angle_deg);

}  // namespace toond::scene
