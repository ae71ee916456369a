#pragma once
#include <string>

#include "scene/bundle.h"
#include "scene/model.h"

namespace toond::scene {

// Imports the bundle's one OBJ file (with its MTL files and map_Kd textures)
// into a Model. Faces are triangulated, missing normals are computed
// (angle-weighted), outline normals are smoothed per position, positions are
// recentred in double precision. Problems that can be worked around (missing
// texture, unknown MTL keyword) become Model::warnings; problems that cannot
// throw ImportError.
Model import_obj_bundle(const Bundle& bundle);

}  // namespace toond::scene
