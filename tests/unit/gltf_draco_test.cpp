// KHR_draco_mesh_compression: compressed files (made here with Draco's own
// encoder) import to the same triangles as their plain twins, through the
// decoder helper process; broken data and a broken decoder are refused
// naming the primitive, never taking the importer down.
#include <gtest/gtest.h>

#include <stdlib.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "fake_helpers.h"
#include "gltf_import_checks.h"
#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "scene/reading/import_error.h"
#include "support/generated_models.h"
#include "support/gltf_draco_writer.h"
#include "support/gltf_twin.h"
#include "support/gltf_writer.h"
#include "support/shared_models.h"
#include "triangle_match.h"

namespace toond::scene {
namespace {

using nlohmann::json;
using test::DracoOptions;
using test::GltfForm;
using test::GltfParts;
using test_checks::import_error;
using test_checks::import_files;
using test_checks::make_bundle;
using test_checks::sphere_parts;
using test_checks::unmatched_triangles;

// Every test finds the helper the build made (the daemon finds it beside
// itself; this test binary lives elsewhere).
class GltfDraco : public ::testing::Test {
 protected:
  void SetUp() override { setenv("TOOND_DRACO_DECODER", TOOND_DRACO_DECODER_PATH, 1); }
};
using GltfDracoMalformed = GltfDraco;

json& draco_extension(GltfParts& parts) {
  return parts.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
}

// The bytes of the first primitive's Draco data, inside `parts.bin`.
std::pair<std::size_t, std::size_t> draco_range(GltfParts& parts) {
  const json& view = parts.json["bufferViews"][draco_extension(parts)["bufferView"].get<std::size_t>()];
  return {view["byteOffset"].get<std::size_t>(), view["byteLength"].get<std::size_t>()};
}

class DracoForms : public ::testing::TestWithParam<GltfForm> {
 protected:
  void SetUp() override { setenv("TOOND_DRACO_DECODER", TOOND_DRACO_DECODER_PATH, 1); }
};

TEST_P(DracoForms, LosslessFileImportsToTheSameTrianglesAsItsPlainTwin) {
  const GltfParts plain = sphere_parts();
  const GltfParts compressed = test::draco_compress(plain);
  ASSERT_TRUE(compressed.json["accessors"][0].contains("count"));
  ASSERT_FALSE(compressed.json["accessors"][0].contains("bufferView"));
  const Model from_plain = import_files(test::pack_gltf(plain, GetParam()));
  const Model from_draco = import_files(test::pack_gltf(compressed, GetParam()));
  EXPECT_EQ(from_draco.mesh.triangle_count(), from_plain.mesh.triangle_count());
  EXPECT_EQ(unmatched_triangles(from_plain, from_draco, 0.0), 0u);
  EXPECT_EQ(unmatched_triangles(from_draco, from_plain, 0.0), 0u);
  EXPECT_FALSE(test_checks::has_warning(from_draco, "KHR_draco_mesh_compression"))
      << test_checks::warnings_of(from_draco);
}

INSTANTIATE_TEST_SUITE_P(Gltf, DracoForms,
                         ::testing::Values(GltfForm::Glb, GltfForm::SeparateFiles, GltfForm::DataUris));

TEST_F(GltfDraco, QuantizedFileMatchesWithinTheQuantizationStep) {
  const GltfParts plain = sphere_parts();
  DracoOptions options;
  options.quantization_bits = 14;
  const Model from_plain = import_files(test::pack_gltf(plain, GltfForm::Glb));
  const Model from_draco = import_files(test::pack_gltf(test::draco_compress(plain, options), GltfForm::Glb));
  EXPECT_EQ(from_draco.mesh.triangle_count(), from_plain.mesh.triangle_count());
  // 14 bits over the sphere's 2 units: a step of 1.2e-4, half of it per axis.
  const double tolerance = std::sqrt(3.0) * 2.0 / ((1 << 14) - 1);
  EXPECT_EQ(unmatched_triangles(from_plain, from_draco, tolerance), 0u);
  EXPECT_EQ(unmatched_triangles(from_draco, from_plain, tolerance), 0u);
  for (std::size_t i = 0; i < from_draco.mesh.positions.size(); ++i) {
    const glm::vec3 radial = glm::normalize(from_draco.mesh.positions[i] - from_draco.mesh.bounds.centre());
    EXPECT_GT(glm::dot(from_draco.mesh.normals[i], radial), 0.97f) << "vertex " << i;
  }
}

TEST_F(GltfDraco, AFallbackIsNotReadWhenTheDracoDataDecodes) {
  DracoOptions options;
  options.keep_fallback = true;
  options.fallback_fill = '\x7f';  // floats of 3.4e38 where the fallback is read
  const GltfParts compressed = test::draco_compress(sphere_parts(), options);
  ASSERT_FALSE(compressed.json.contains("extensionsRequired"));
  const Model m = import_files(test::pack_gltf(compressed, GltfForm::Glb));
  EXPECT_NEAR(m.mesh.bounds.max.x - m.mesh.bounds.min.x, 2.0f, 1e-3f);
}

TEST_F(GltfDraco, AttributesMapByTheirIdsOntoColoursAndTextureCoordinates) {
  test::GltfPrimitive quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.colours = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  test::GltfDocument doc;
  doc.meshes = {{quad}};
  const GltfParts compressed = test::draco_compress(test::build_gltf(doc));
  const Model m = import_files(test::pack_gltf(compressed, GltfForm::Glb));
  ASSERT_EQ(m.mesh.triangle_count(), 2u);
  ASSERT_TRUE(m.has_vertex_colors);
  for (std::size_t i = 0; i < m.mesh.positions.size(); ++i) {
    const glm::vec3 p = glm::vec3(m.mesh.origin) + m.mesh.positions[i];
    // Each corner keeps its own colour and texture coordinates (v flipped on import).
    EXPECT_NEAR(m.mesh.texcoords[i].x, p.x, 1e-6f);
    EXPECT_NEAR(m.mesh.texcoords[i].y, 1.0f - p.y, 1e-6f);
    const glm::vec3 expected = p.x < 0.5f ? (p.y < 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(1, 1, 1))
                                          : (p.y < 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
    EXPECT_EQ(m.mesh.colors[i], expected) << "vertex " << i;
  }
}

// --- broken data ---

TEST_F(GltfDracoMalformed, GarbageDataIsRefusedNamingThePrimitive) {
  GltfParts parts = test::draco_compress(sphere_parts());
  const auto [offset, length] = draco_range(parts);
  for (std::size_t i = 0; i < length; ++i) parts.bin[offset + i] = static_cast<char>((i * 131 + 7) & 0xff);
  const std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("mesh 0 primitive 0 (KHR_draco_mesh_compression) cannot be decoded"), std::string::npos)
      << error;
}

TEST_F(GltfDracoMalformed, TruncatedOrDamagedDataIsRefusedOrDecodesToCheckedData) {
  GltfParts truncated = test::draco_compress(sphere_parts());
  const auto [offset, length] = draco_range(truncated);
  truncated.json["bufferViews"][draco_extension(truncated)["bufferView"].get<std::size_t>()]["byteLength"] = length / 2;
  const std::string error = import_error(test::pack_gltf(truncated, GltfForm::Glb));
  EXPECT_NE(error.find("mesh 0 primitive 0 (KHR_draco_mesh_compression)"), std::string::npos) << error;

  const GltfParts clean = test::draco_compress(sphere_parts());
  for (std::size_t seed = 1; seed <= 12; ++seed) {
    GltfParts damaged = clean;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t at = offset + (seed * 7919 + k * 104729) % length;
      damaged.bin[at] = static_cast<char>(damaged.bin[at] ^ static_cast<char>(seed * 37 + k + 1));
    }
    test_checks::expect_refused_or_sound(test::pack_gltf(damaged, GltfForm::Glb));
  }
}

TEST_F(GltfDracoMalformed, CountsThatDoNotMatchTheDecodedMeshAreRefused) {
  GltfParts parts = test::draco_compress(sphere_parts());
  const json primitive = parts.json["meshes"][0]["primitives"][0];
  json& position = parts.json["accessors"][primitive["attributes"]["POSITION"].get<std::size_t>()];
  const std::size_t points = position["count"];
  position["count"] = points + 1;
  std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("decodes to " + std::to_string(points) + " points, but its POSITION accessor counts " +
                       std::to_string(points + 1)),
            std::string::npos)
      << error;

  parts = test::draco_compress(sphere_parts());
  json& indices = parts.json["accessors"][primitive["indices"].get<std::size_t>()];
  indices["count"] = indices["count"].get<std::size_t>() - 3;
  error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("triangles, but its indices make"), std::string::npos) << error;

  parts = test::draco_compress(sphere_parts());
  json& normal = parts.json["accessors"][primitive["attributes"]["NORMAL"].get<std::size_t>()];
  normal["count"] = points - 1;
  error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("but its NORMAL accessor counts"), std::string::npos) << error;
}

TEST_F(GltfDracoMalformed, AttributeIdsThatDoNotFitAreRefused) {
  GltfParts parts = test::draco_compress(sphere_parts());
  draco_extension(parts)["attributes"]["POSITION"] = 99;
  std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("no attribute with id 99"), std::string::npos) << error;

  // TEXCOORD_0 (two components) pointed at the normals (three).
  parts = test::draco_compress(sphere_parts());
  draco_extension(parts)["attributes"]["TEXCOORD_0"] = draco_extension(parts)["attributes"]["NORMAL"];
  error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("decodes TEXCOORD_0 with 3 components, but its accessor has 2"), std::string::npos) << error;

  parts = test::draco_compress(sphere_parts());
  draco_extension(parts)["attributes"]["NORMAL"] = -1;
  error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("gives NORMAL an attribute id that is not a non-negative integer"), std::string::npos) << error;

  parts = test::draco_compress(sphere_parts());
  draco_extension(parts).erase("bufferView");
  error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("mesh 0 primitive 0 (KHR_draco_mesh_compression) has no valid bufferView"), std::string::npos)
      << error;
}

TEST_F(GltfDracoMalformed, ADecoderThatCrashesHangsOrBabblesIsARefusalNotACrash) {
  const auto files = test::pack_gltf(test::draco_compress(sphere_parts()), GltfForm::Glb);
  test_checks::FakeHelpers fakes;

  setenv("TOOND_DRACO_DECODER", fakes.make("crash", "kill -SEGV $$").c_str(), 1);
  std::string error = import_error(files);
  EXPECT_NE(
      error.find("mesh 0 primitive 0 (KHR_draco_mesh_compression) cannot be decoded: the decoder crashed (SIGSEGV)"),
      std::string::npos)
      << error;

  setenv("TOOND_DRACO_DECODER", fakes.make("babble", "cat >/dev/null; printf 'TDM1 not a mesh at all'").c_str(), 1);
  error = import_error(files);
  EXPECT_NE(error.find("the decoder's answer is not a mesh"), std::string::npos) << error;

  // A hang ends at the import's own time limit.
  setenv("TOOND_DRACO_DECODER", fakes.make("hang", "exec sleep 60").c_str(), 1);
  ImportLimits limits;
  limits.max_seconds = 1.0;
  limits.deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  const auto started = std::chrono::steady_clock::now();
  error = import_error(files, limits);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(10));
  EXPECT_NE(error.find("limit --max-import-seconds"), std::string::npos) << error;

  setenv("TOOND_DRACO_DECODER", "/nonexistent/toond-draco-decode", 1);
  error = import_error(files);
  EXPECT_NE(error.find("cannot be started"), std::string::npos) << error;
  // The client learns which helper, not where the daemon keeps it.
  EXPECT_NE(error.find("toond-draco-decode"), std::string::npos) << error;
  EXPECT_EQ(error.find("/nonexistent"), std::string::npos) << error;
}

// --- the shared OBJ models' glTF twins, compressed ---

class SharedDracoTwin : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { setenv("TOOND_DRACO_DECODER", TOOND_DRACO_DECODER_PATH, 1); }
};

TEST_P(SharedDracoTwin, ImportsLikeThePlainTwinWithinTheQuantizationStep) {
  TOOND_REQUIRE_SHARED_MODELS();
  const Bundle bundle = test_checks::shared_model_bundle(GetParam());
  const GltfParts plain = test::build_gltf(test::gltf_twin(import_obj_bundle(bundle), bundle));
  DracoOptions options;
  options.quantization_bits = 16;
  const Model from_plain = import_files(test::pack_gltf(plain, GltfForm::Glb));
  const Model from_draco = import_files(test::pack_gltf(test::draco_compress(plain, options), GltfForm::Glb));
  EXPECT_EQ(from_draco.mesh.triangle_count(), from_plain.mesh.triangle_count());
  const glm::dvec3 size = glm::dvec3(from_plain.mesh.bounds.max - from_plain.mesh.bounds.min);
  const double tolerance = std::sqrt(3.0) * std::max({size.x, size.y, size.z}) / ((1 << 16) - 1);
  EXPECT_EQ(unmatched_triangles(from_plain, from_draco, tolerance), 0u);
  EXPECT_EQ(unmatched_triangles(from_draco, from_plain, tolerance), 0u);
  EXPECT_EQ(from_draco.textures.size(), from_plain.textures.size());
}

INSTANTIATE_TEST_SUITE_P(Gltf, SharedDracoTwin, ::testing::Values("spot", "kenney-cube-pet-dog", "windmill"));

}  // namespace
}  // namespace toond::scene
