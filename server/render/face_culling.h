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
#include <glm/glm.hpp>

#include "scene/model.h"

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


}  // namespace toond::render
