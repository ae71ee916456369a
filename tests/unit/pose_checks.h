#pragma once
// Checks shared by the tests that pose a model against a moment an exporter
// wrote down itself (Blender's OBJ of its own armature deform).
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::scene::test_checks {

// The `v x y z` positions of an OBJ file's text, in file order.
inline std::vector<glm::dvec3> obj_positions(const std::string& obj_text) {
  std::vector<glm::dvec3> positions;
  std::istringstream obj(obj_text);
  for (std::string line; std::getline(obj, line);) {
    glm::dvec3 v;
    if (std::sscanf(line.c_str(), "v %lf %lf %lf", &v.x, &v.y, &v.z) == 3) positions.push_back(v);
  }
  return positions;
}

// Every vertex of `model` posed at `time` of clip `clip`, in the file's
// frame (the mesh's origin added back).
inline std::vector<glm::dvec3> posed_points(const Model& model, std::size_t clip, double time) {
  const Rig& rig = *model.rig;
  const PosedVertices posed = pose_vertices(model.mesh, rig, pose_nodes(rig, &rig.clips[clip], time));
  std::vector<glm::dvec3> points;
  for (const glm::vec3& p : posed.positions) points.push_back(glm::dvec3(p) + model.mesh.origin);
  return points;
}

}  // namespace toond::scene::test_checks
