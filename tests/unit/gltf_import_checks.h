#pragma once
// What the glTF import tests share: importing generated files as an
// upload would, the message an import refuses them with, and a UV sphere
// as glTF.
#include <string>

#include <gtest/gtest.h>

#include "model_checks.h"
#include "scene/bundle_import.h"
#include "scene/import_error.h"
#include "scene/obj_import.h"
#include "support/generated_models.h"
#include "support/gltf_twin.h"
#include "support/gltf_writer.h"

namespace toond::scene::test_checks {

inline Model import_files(const test::GltfFiles& files, const ImportLimits& limits = {}) {
  return import_bundle(make_bundle(files), limits);
}

// The message of the ImportError that importing `files` throws.
inline std::string import_error(const test::GltfFiles& files, const ImportLimits& limits = {}) {
  try {
    import_files(files, limits);
  } catch (const ImportLimitError& e) {
    return std::string("limit ") + e.limit() + ": " + e.what();
  } catch (const ImportError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the import succeeded";
  return {};
}

// A UV sphere with normals and texture coordinates, as glTF.
inline test::GltfParts sphere_parts() {
  const Bundle bundle = make_bundle({{"sphere.obj", test::sphere_obj(24, 12)}});
  return test::build_gltf(test::gltf_twin(import_obj_bundle(bundle), bundle));
}

}  // namespace toond::scene::test_checks
