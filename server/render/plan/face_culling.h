#pragma once
// Which faces of a closed object a draw may skip. Pure maths, no GL calls,
// so it is unit tested without a context.
//
// A closed surface (scene::Enclosure) seen from outside shows only faces
// turned toward the camera; the rest lie behind them. That holds while the
// near and far planes cut nothing off the object: a clipped surface opens,
// and its inside faces would show through the cut (a camera inside the
// bounds). The object's box must lie wholly between them, else nothing is
// skipped.
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/model.h"

namespace toond::render {

enum class HiddenFaces {
  None,   // draw both sides
  Back,   // counter-clockwise on screen is the visible side (GL's front)
  Front,  // the mesh winds the other way (inside out, or mirrored)
};

// `model` takes the mesh's coordinates (those of `bounds`) into the scene;
// `view_projection` takes the scene to clip space. A mirroring transform
// (negative determinant) swaps which side shows. `reach` (scene units) is
// how far the drawn surface may stand out of `bounds`: an outline hull's
// offset, whose corners must stay within the depth range too.
HiddenFaces hidden_faces(scene::Enclosure enclosure, const glm::dmat4& model, const glm::dmat4& view_projection,
                         const scene::Bounds& bounds, double reach = 0.0);

// Which faces of an object a pass skips.
struct FaceSkip {
  HiddenFaces hidden = HiddenFaces::None;
  // The object has holes whose caps may face the camera: the skipped side
  // is drawn after all wherever one of them shows.
  bool unless_caps_show = false;
};

// Where the camera is and which way it looks, in scene coordinates.
struct Viewer {
  glm::dvec3 eye{0.0};                 // perspective views
  glm::dvec3 forward{0.0, 0.0, -1.0};  // orthographic views: the direction of every ray
  bool orthographic = false;
};

// Whether every cap over the object's holes (scene::Mesh::caps) turns its
// outer side away from the viewer: then every ray meets the mesh's front
// faces before it could pass a hole (it reaches a hole from inside the
// volume), and what `hidden_faces` allows holds for the open mesh too.
// Caps of no area cover no pixel and do not count. (An outline hull's holes
// move with its offset, so the hull of an open mesh is drawn whole.)
bool caps_face_away(const std::vector<glm::vec3>& caps, scene::Enclosure enclosure, const glm::dmat4& model,
                    const Viewer& viewer);

}  // namespace toond::render
