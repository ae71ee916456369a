#pragma once
// Hull and wireframe lines take their colour the same way: a fixed colour,
// or per material (its colour darkened, or the texture under the line).
#include <functional>

#include "render/passes/object_draw.h"
#include "render/passes/pass_context.h"

namespace toond::render {

// Draws every object with the outline program in use, skipping the faces
// `faces(i)` says.
void draw_outline_objects(PassContext& context, const std::function<FaceSkip(std::size_t)>& faces);

// Whether the outline's colour or alpha test comes from each material, so
// objects are drawn material by material.
bool outline_per_material(const FrameContext& frame);

}  // namespace toond::render
