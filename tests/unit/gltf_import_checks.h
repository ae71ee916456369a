#pragma once
// What the glTF import tests share: importing generated files as an
// upload would, the message an import refuses them with, and a UV sphere
// as glTF.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "http/import_limit_flag.h"
#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "scene/reading/import_error.h"
#include "support/generated_models.h"
#include "support/gltf_twin.h"
#include "support/gltf_writer.h"
#include "support/shared_models.h"

namespace toond::scene::test_checks {

inline Model import_files(const test::GltfFiles& files, const ImportLimits& limits = {}) {
  return import_bundle(make_bundle(files), limits);
}

// The message of the ImportError that importing `files` throws; one over a
// limit is worded as the daemon's answer words it, after "limit <flag>: ".
inline std::string import_error(const test::GltfFiles& files, const ImportLimits& limits = {}) {
  try {
    import_files(files, limits);
  } catch (const ImportLimitError& e) {
    const std::string_view flag = http::import_limit_flag(e.limit());
    return "limit " + std::string(flag) + ": " + e.message_naming(flag);
  } catch (const ImportError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the import succeeded";
  return {};
}

// A unit cube: 24 vertices (4 per face, with the face's normal), 12
// triangles, counter-clockwise seen from outside.
inline test::GltfPrimitive cube_primitive() {
  test::GltfPrimitive p;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a) {
    for (const float sign : {1.0f, -1.0f}) {
      const glm::vec3 n = axes[a] * sign;
      const glm::vec3 u = axes[(a + 1) % 3] * sign;
      const glm::vec3 v = axes[(a + 2) % 3];
      const auto base = static_cast<std::uint32_t>(p.positions.size());
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        p.positions.push_back(n + u * c.x + v * c.y);
        p.normals.push_back(n);
        p.texcoords.push_back((c + 1.0f) * 0.5f);
      }
      p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  }
  return p;
}

// Importing `files` either refuses them (ImportError) or gives a mesh whose
// every index is in range: for damaged data, which may still decode.
inline void expect_refused_or_sound(const test::GltfFiles& files) {
  try {
    const Model m = import_files(files);
    for (const auto i : m.mesh.indices) ASSERT_LT(i, m.mesh.positions.size());
  } catch (const ImportError&) {
    // A refusal is the expected answer; a crash or another exception is not.
  }
}

// Every file of a shared model's folder, as an upload of that folder.
inline Bundle shared_model_bundle(const std::string& name) {
  Bundle bundle;
  const auto dir = test::shared_models_dir() / name;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) {
      bundle.add(std::filesystem::relative(entry.path(), dir).generic_string(), test::read_file(entry.path()));
    }
  }
  return bundle;
}

// A UV sphere with normals and texture coordinates, as glTF.
inline test::GltfParts sphere_parts() {
  const Bundle bundle = make_bundle({{"sphere.obj", test::sphere_obj(24, 12)}});
  return test::build_gltf(test::gltf_twin(import_obj_bundle(bundle), bundle));
}

}  // namespace toond::scene::test_checks
