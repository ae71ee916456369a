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

}  // namespace toond::test
