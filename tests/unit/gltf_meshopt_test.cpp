// EXT_meshopt_compression: compressed files (made here with meshoptimizer's
// own encoders, the way gltfpack makes them) import to the same triangles
// as their plain twins, and broken streams are refused naming the view.
#include <gtest/gtest.h>

#include <meshoptimizer.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "gltf_import_checks.h"
#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "scene/reading/import_error.h"
#include "support/generated_models.h"
#include "support/gltf_meshopt_writer.h"
#include "support/gltf_twin.h"
#include "support/gltf_writer.h"
#include "support/shared_models.h"
#include "triangle_match.h"

namespace toond::scene {
namespace {

using nlohmann::json;
using test::GltfForm;
using test::GltfParts;
using test::MeshoptFallback;
using test_checks::import_error;
using test_checks::import_files;
using test_checks::make_bundle;
using test_checks::sphere_parts;
using test_checks::unmatched_triangles;

json& extension_of(GltfParts& parts, int view) {
  return parts.json["bufferViews"][view]["extensions"]["EXT_meshopt_compression"];
}

// The first view compressed in `mode`.
int first_view(const GltfParts& parts, const std::string& mode) {
  const json& views = parts.json["bufferViews"];
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (views[i].contains("extensions") && views[i]["extensions"]["EXT_meshopt_compression"]["mode"] == mode) {
      return static_cast<int>(i);
    }
  }
  ADD_FAILURE() << "no view in mode " << mode;
  return -1;
}

void expect_same_model(const Model& plain, const Model& compressed) {
  EXPECT_EQ(compressed.mesh.triangle_count(), plain.mesh.triangle_count());
  EXPECT_EQ(compressed.mesh.positions.size(), plain.mesh.positions.size());
  // The codecs are lossless; only the triangles' starting corners may turn.
  EXPECT_EQ(unmatched_triangles(plain, compressed, 0.0), 0u);
  EXPECT_EQ(unmatched_triangles(compressed, plain, 0.0), 0u);
  EXPECT_EQ(compressed.mesh.texcoords.size(), plain.mesh.texcoords.size());
}

class MeshoptForms : public ::testing::TestWithParam<std::tuple<GltfForm, MeshoptFallback>> {};

TEST_P(MeshoptForms, CompressedFileImportsLikeItsPlainTwin) {
  const auto [form, fallback] = GetParam();
  const GltfParts plain = sphere_parts();
  const GltfParts compressed = test::meshopt_compress(plain, fallback);
  const Model from_plain = import_files(test::pack_gltf(plain, form));
  const Model from_compressed = import_files(test::pack_gltf(compressed, form));
  expect_same_model(from_plain, from_compressed);
  EXPECT_FALSE(test_checks::has_warning(from_compressed, "EXT_meshopt_compression"))
      << test_checks::warnings_of(from_compressed);
}

INSTANTIATE_TEST_SUITE_P(
    Gltf, MeshoptForms,
    ::testing::Combine(::testing::Values(GltfForm::Glb, GltfForm::SeparateFiles, GltfForm::DataUris),
                       ::testing::Values(MeshoptFallback::StandIn, MeshoptFallback::UntaggedStandIn,
                                         MeshoptFallback::Zeros)));

TEST(GltfMeshopt, AFallbackWithDataIsNotReadWhenTheStreamDecodes) {
  // The fallback holds zeros: read instead of the stream, every vertex
  // would lie at the origin.
  const GltfParts compressed = test::meshopt_compress(sphere_parts(), MeshoptFallback::Zeros);
  ASSERT_FALSE(compressed.json.contains("extensionsRequired"));
  const Model m = import_files(test::pack_gltf(compressed, GltfForm::Glb));
  EXPECT_NEAR(m.mesh.bounds.max.x - m.mesh.bounds.min.x, 2.0f, 1e-3f);
}

TEST(GltfMeshopt, TrianglesAndIndexSequencesAndStripsDecode) {
  test::GltfPrimitive strip;
  strip.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  strip.indices = {0, 1, 2, 3, 4, 5};
  strip.mode = 5;
  test::GltfPrimitive list = strip;
  list.indices = {0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5};
  list.mode = 4;
  for (auto& p : list.positions) p.z += 1.0f;
  test::GltfDocument doc;
  doc.meshes = {{strip, list}};
  const GltfParts plain = test::build_gltf(doc);
  const GltfParts compressed = test::meshopt_compress(plain);
  ASSERT_GE(first_view(compressed, "INDICES"), 0);
  ASSERT_GE(first_view(compressed, "TRIANGLES"), 0);
  const Model m = import_files(test::pack_gltf(compressed, GltfForm::Glb));
  EXPECT_EQ(m.mesh.triangle_count(), 8u);
  expect_same_model(import_files(test::pack_gltf(plain, GltfForm::Glb)), m);
}

// The cube of gltfpack's usual output: positions as normalised shorts
// (KHR_mesh_quantization), normals through the octahedral filter, texture
// coordinates through the exponential filter, colours through the
// quaternion filter, 16-bit indices; each in a stream of its own.
TEST(GltfMeshopt, QuantizedDataThroughEveryFilterFeedsTheAccessors) {
  test::GltfPrimitive cube = test_checks::cube_primitive();
  // Texture coordinates inside [0.125, 0.625], away from the ends.
  for (glm::vec2& t : cube.texcoords) t = t * 0.5f + 0.125f;
  const std::size_t n = cube.positions.size();
  GltfParts parts;
  parts.json = {{"asset", {{"version", "2.0"}}}, {"buffers", {{{"byteLength", 0}}}}, {"bufferViews", json::array()}};

  std::vector<std::int16_t> positions;
  for (const glm::vec3& p : cube.positions) {
    for (int c = 0; c < 3; ++c) positions.push_back(static_cast<std::int16_t>(std::lround(p[c] * 32767.0f)));
    positions.push_back(0);  // a stride of 8, as the attribute codec wants a multiple of 4
  }
  const int position_view = test::add_meshopt_view(parts, positions.data(), n, 8, "ATTRIBUTES");

  std::vector<float> normal_input;
  for (const glm::vec3& v : cube.normals) normal_input.insert(normal_input.end(), {v.x, v.y, v.z, 0.0f});
  std::vector<std::int8_t> normals(n * 4);
  meshopt_encodeFilterOct(normals.data(), n, 4, 8, normal_input.data());
  const int normal_view = test::add_meshopt_view(parts, normals.data(), n, 4, "ATTRIBUTES", "OCTAHEDRAL");

  std::vector<float> uv_input;
  for (const glm::vec2& t : cube.texcoords) uv_input.insert(uv_input.end(), {t.x, t.y});
  std::vector<std::uint32_t> uvs(n * 2);
  meshopt_encodeFilterExp(uvs.data(), n, 8, 15, uv_input.data());
  const int uv_view = test::add_meshopt_view(parts, uvs.data(), n, 8, "ATTRIBUTES", "EXPONENTIAL");

  // A unit quaternion as a colour: each component 0.5, linear.
  const std::vector<float> quaternion_input(n * 4, 0.5f);
  std::vector<std::int16_t> colours(n * 4);
  meshopt_encodeFilterQuat(colours.data(), n, 8, 12, quaternion_input.data());
  const int colour_view = test::add_meshopt_view(parts, colours.data(), n, 8, "ATTRIBUTES", "QUATERNION");

  std::vector<std::uint16_t> indices(cube.indices.begin(), cube.indices.end());
  const int index_view = test::add_meshopt_view(parts, indices.data(), indices.size(), 2, "TRIANGLES");

  parts.json["bufferViews"][position_view]["byteStride"] = 8;
  parts.json["bufferViews"][normal_view]["byteStride"] = 4;
  parts.json["bufferViews"][uv_view]["byteStride"] = 8;
  parts.json["bufferViews"][colour_view]["byteStride"] = 8;
  parts.json["accessors"] = {
      {{"bufferView", position_view},
       {"componentType", 5122},
       {"normalized", true},
       {"count", n},
       {"type", "VEC3"},
       {"min", {-1, -1, -1}},
       {"max", {1, 1, 1}}},
      {{"bufferView", normal_view}, {"componentType", 5120}, {"normalized", true}, {"count", n}, {"type", "VEC3"}},
      {{"bufferView", uv_view}, {"componentType", 5126}, {"count", n}, {"type", "VEC2"}},
      {{"bufferView", colour_view}, {"componentType", 5122}, {"normalized", true}, {"count", n}, {"type", "VEC4"}},
      {{"bufferView", index_view}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}}};
  const json primitive = {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}, {"COLOR_0", 3}}},
                          {"indices", 4}};
  parts.json["meshes"] = json::array({{{"primitives", json::array({primitive})}}});
  parts.json["nodes"] = json::array({{{"mesh", 0}}});
  parts.json["extensionsUsed"].push_back("KHR_mesh_quantization");
  parts.json["extensionsRequired"].push_back("KHR_mesh_quantization");

  const Model m = import_files(test::pack_gltf(parts, GltfForm::Glb));
  ASSERT_EQ(m.mesh.triangle_count(), 12u);
  EXPECT_NEAR(m.mesh.origin.x + m.mesh.bounds.min.x, -1.0, 1e-4);
  EXPECT_NEAR(m.mesh.origin.z + m.mesh.bounds.max.z, 1.0, 1e-4);
  for (std::size_t i = 0; i < m.mesh.positions.size(); ++i) {
    // Each face keeps its own normal: the axis it faces along.
    const glm::vec3 p = glm::vec3(m.mesh.origin) + m.mesh.positions[i];
    const glm::vec3 normal = m.mesh.normals[i];
    const int axis = std::abs(normal.x) > 0.99f ? 0 : std::abs(normal.y) > 0.99f ? 1 : 2;
    EXPECT_GT(std::abs(normal[axis]), 0.99f) << "vertex " << i;
    EXPECT_NEAR(p[axis], normal[axis] > 0 ? 1.0f : -1.0f, 1e-3f) << "vertex " << i;
    // The texture coordinates were 0.125 or 0.625 (v flipped on import).
    for (int c = 0; c < 2; ++c) {
      const float t = c == 0 ? m.mesh.texcoords[i].x : 1.0f - m.mesh.texcoords[i].y;
      EXPECT_TRUE(std::abs(t - 0.125f) < 1e-4f || std::abs(t - 0.625f) < 1e-4f) << t;
    }
  }
  ASSERT_TRUE(m.has_vertex_colors);
  for (const glm::vec3& c : m.mesh.colors) EXPECT_NEAR(c.r, 0.7354f, 2e-3f) << "linear 0.5 is sRGB 0.735";
}

// --- broken and hostile streams ---

TEST(GltfMeshoptMalformed, ATruncatedStreamIsRefusedNamingTheView) {
  GltfParts parts = test::meshopt_compress(sphere_parts());
  const int view = first_view(parts, "ATTRIBUTES");
  json& extension = extension_of(parts, view);
  extension["byteLength"] = extension["byteLength"].get<std::size_t>() / 2;
  const std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("buffer view " + std::to_string(view) + " (EXT_meshopt_compression) cannot be decoded"),
            std::string::npos)
      << error;

  parts = test::meshopt_compress(sphere_parts());
  const int triangles = first_view(parts, "TRIANGLES");
  json& index_extension = extension_of(parts, triangles);
  index_extension["byteLength"] = index_extension["byteLength"].get<std::size_t>() - 20;
  const std::string index_error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(
      index_error.find("buffer view " + std::to_string(triangles) + " (EXT_meshopt_compression) cannot be decoded"),
      std::string::npos)
      << index_error;
}

TEST(GltfMeshoptMalformed, DamagedStreamBytesAreRefusedOrDecodeToCheckedData) {
  const GltfParts clean = test::meshopt_compress(sphere_parts());
  for (std::size_t seed = 1; seed <= 40; ++seed) {
    GltfParts parts = clean;
    // Scramble a stretch of the compressed bytes (buffer 0 holds only streams here).
    for (std::size_t k = 0; k < 16; ++k) {
      const std::size_t at = (seed * 7919 + k * 104729) % parts.bin.size();
      parts.bin[at] = static_cast<char>(parts.bin[at] ^ static_cast<char>(seed * 37 + k));
    }
    test_checks::expect_refused_or_sound(test::pack_gltf(parts, GltfForm::Glb));
  }
}

TEST(GltfMeshoptMalformed, ACountLargerThanTheBufferIsRefusedBeforeAllocating) {
  GltfParts parts = test::meshopt_compress(sphere_parts());
  const int view = first_view(parts, "ATTRIBUTES");
  json& extension = extension_of(parts, view);
  const std::size_t stride = extension["byteStride"];
  // A billion elements said to hide in a few hundred bytes.
  extension["count"] = 1'000'000'000;
  parts.json["bufferViews"][view]["byteLength"] = 1'000'000'000 * stride;
  const auto files = test::pack_gltf(parts, GltfForm::Glb);
  // Without limits (a stored model), the stream's own size refuses it.
  const std::string error = import_error(files);
  EXPECT_NE(error.find("buffer view " + std::to_string(view) + " (EXT_meshopt_compression) declares 1000000000"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("compressed bytes can hold"), std::string::npos) << error;
  ImportLimits limits;
  limits.max_vertices = 100'000;
  const std::string limited = import_error(files, limits);
  EXPECT_NE(limited.find("limit --max-vertices"), std::string::npos) << limited;
  EXPECT_NE(limited.find("decompresses to 1000000000 vertices"), std::string::npos) << limited;

  // The stream's range past the end of its buffer.
  parts = test::meshopt_compress(sphere_parts());
  extension_of(parts, view)["byteOffset"] = parts.bin.size() - 8;
  const std::string past = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(past.find("past the end of buffer 0"), std::string::npos) << past;
}

TEST(GltfMeshoptMalformed, ACountThatIsNotTheViewsLengthIsRefused) {
  GltfParts parts = test::meshopt_compress(sphere_parts());
  const int view = first_view(parts, "ATTRIBUTES");
  extension_of(parts, view)["count"] = extension_of(parts, view)["count"].get<std::size_t>() + 1;
  const std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("which is not its view's byteLength"), std::string::npos) << error;
}

TEST(GltfMeshoptMalformed, ModesFiltersAndStridesOutsideTheRulesAreNamed) {
  const auto error_with = [](const std::string& mode, const json& change) {
    GltfParts parts = test::meshopt_compress(sphere_parts());
    json& extension = extension_of(parts, first_view(parts, mode));
    extension.merge_patch(change);
    return import_error(test::pack_gltf(parts, GltfForm::Glb));
  };
  EXPECT_NE(error_with("ATTRIBUTES", {{"mode", "ZIGZAG"}}).find("has no mode"), std::string::npos);
  EXPECT_NE(error_with("ATTRIBUTES", {{"filter", "BLUR"}}).find("has a filter other than"), std::string::npos);
  EXPECT_NE(error_with("ATTRIBUTES", {{"filter", "QUATERNION"}}).find("the quaternion filter needs 8"),
            std::string::npos);
  EXPECT_NE(error_with("TRIANGLES", {{"filter", "EXPONENTIAL"}}).find("index streams cannot have"), std::string::npos);
  EXPECT_NE(error_with("TRIANGLES", {{"byteStride", 8}}).find("index streams need 2 or 4"), std::string::npos);
  EXPECT_NE(error_with("ATTRIBUTES", {{"buffer", nullptr}}).find("has no valid buffer"), std::string::npos);
  EXPECT_NE(error_with("ATTRIBUTES", {{"buffer", 7}}).find("refers to buffer 7"), std::string::npos);
  // A stream may not come from the stand-in buffer.
  EXPECT_NE(error_with("ATTRIBUTES", {{"buffer", 1}}).find("a fallback buffer that holds no data"), std::string::npos);
}

TEST(GltfMeshoptMalformed, APlainViewInTheStandInBufferIsRefused) {
  GltfParts parts = test::meshopt_compress(sphere_parts());
  const int view = first_view(parts, "ATTRIBUTES");
  parts.json["bufferViews"][view].erase("extensions");
  const std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("buffer view " + std::to_string(view) + " lies in buffer 1"), std::string::npos) << error;
}

// --- the shared OBJ models' glTF twins, compressed ---

class SharedMeshoptTwin : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedMeshoptTwin, ImportsLikeThePlainTwin) {
  TOOND_REQUIRE_SHARED_MODELS();
  const Bundle bundle = test_checks::shared_model_bundle(GetParam());
  const GltfParts plain = test::build_gltf(test::gltf_twin(import_obj_bundle(bundle), bundle));
  const Model from_plain = import_files(test::pack_gltf(plain, GltfForm::Glb));
  const Model from_compressed = import_files(test::pack_gltf(test::meshopt_compress(plain), GltfForm::Glb));
  expect_same_model(from_plain, from_compressed);
  EXPECT_EQ(from_compressed.textures.size(), from_plain.textures.size());
}

INSTANTIATE_TEST_SUITE_P(Gltf, SharedMeshoptTwin, ::testing::Values("spot", "kenney-cube-pet-dog", "windmill"));

}  // namespace
}  // namespace toond::scene
