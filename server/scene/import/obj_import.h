#pragma once
#include <string>

#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// Imports the bundle's one OBJ file (with its MTL files, their map_Kd colour
// textures and map_Bump / bump / norm normal maps, and "v x y z r g b"
// vertex colours) into a Model. Faces are triangulated; the rest is
// build_mesh's (mesh_builder.h): missing normals are computed
// (angle-weighted), outline normals are smoothed per position, tangents are
// derived, positions are recentred in double precision. Problems that can be
// worked around (missing texture, unknown MTL keyword) become
// Model::warnings; problems that cannot throw ImportError.
// Callers that take any model file use import_bundle (bundle_import.h).
Model import_obj_bundle(const Bundle& bundle, const ImportLimits& limits = {}, const ImportChoices& choices = {});

}  // namespace toond::scene
