#pragma once
// The glTF twin of an imported model: the same vertices, triangles,
// materials and image files written as glTF, so a test can check that the
// glTF importer makes what the OBJ importer made.
#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "support/gltf_writer.h"

namespace toond::test {

// One mesh with a primitive per submesh, placed by a node translation at
// the model's origin (kept in double); texture images are the bundle files
// the model's textures came from.
GltfDocument gltf_twin(const scene::Model& model, const scene::Bundle& bundle);

}  // namespace toond::test
