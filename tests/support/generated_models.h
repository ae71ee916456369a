#pragma once
// OBJ text for test models made here: a UV sphere with exact normals and a
// hard-edged cube, at any centre and scale.
#include <string>

#include <glm/glm.hpp>

namespace toond::test {

std::string sphere_obj(int segments, int rings, double radius = 1.0, glm::dvec3 centre = glm::dvec3(0.0));
std::string cube_obj(double half_size = 1.0, glm::dvec3 centre = glm::dvec3(0.0));
// A flat disk in the XY plane facing +Z, a fan of `segments` triangles.
std::string disk_obj(int segments, double radius = 1.0);
// The lower half of a unit sphere, open at the top (y = 0): a bowl, whose
// inside shows from above.
std::string bowl_obj(int segments, int rings);

// A unit UV sphere as exporters write one: every vertex computed from sin
// and cos, so the seam's two vertex rows and a pole's vertices lie a
// rounding error apart (not bitwise equal), with texture coordinates.
struct ExporterSphere {
  int segments = 192;
  int rings = 96;
  // Extra, deterministic scatter of the pole and seam copies, in radii
  // (0: only what sin and cos leave, about 1e-16).
  double jitter = 0.0;
  enum class Normals { Smooth, PerFace, None } normals = Normals::Smooth;
};
std::string exporter_sphere_obj(const ExporterSphere& sphere);

}  // namespace toond::test
