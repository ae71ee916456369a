#pragma once
#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// Imports the bundle's one .m file: Hugues Hoppe's mesh format, as the
// reference cel-shading model viewer reads it.
//
//   # comment
//   Vertex 1  0 0 0  {normal=(0 0 1) uv=(0 0) rgb=(1 0 0)}
//   Vertex 7  1 0 0
//   Face 1  1 7 3
//
// Vertex ids are integers as written (need not be contiguous or ordered);
// faces name them and may have more than three (fan-triangulated). The
// {...} part is optional; normal, uv and rgb are read from it, other
// attributes are ignored, and face attributes too. Other lines (Edge,
// Corner, ...) are ignored with one warning. The model gets one material,
// "default". After parsing, the mesh goes through the same build_mesh as an
// OBJ (mesh_builder.h). A line that cannot be read, a repeated vertex id
// or a face naming a vertex id no Vertex line defines is an ImportError
// naming the file and the line.
Model import_m_bundle(const Bundle& bundle, const ImportLimits& limits = {}, const ImportChoices& choices = {});

}  // namespace toond::scene
