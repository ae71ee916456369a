// glTF 2.0 import: the forms an upload takes, what is read from it, and the
// broken and hostile files it must refuse with a clear answer.
#include <gtest/gtest.h>

#include <webp/encode.h>

#include <cmath>
#include <filesystem>

#include "gltf_import_checks.h"
#include "model_checks.h"
#include "scene/gltf/gltf_import.h"
#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/reading/import_error.h"
#include "support/gltf_twin.h"
#include "support/gltf_writer.h"
#include "support/shared_models.h"

namespace toond::scene {
namespace {

using nlohmann::json;
using test::GltfDocument;
using test::GltfForm;
using test::GltfPrimitive;
using test_checks::cube_primitive;
using test_checks::has_warning;
using test_checks::import_error;
using test_checks::import_files;
using test_checks::make_bundle;
using test_checks::tiny_png;
using test_checks::warnings_of;

GltfDocument cube_document() {
  GltfDocument doc;
  doc.meshes = {{cube_primitive()}};
  return doc;
}

test::GltfNode node(int mesh, std::vector<int> children = {}) {
  test::GltfNode n;
  n.mesh = mesh;
  n.children = std::move(children);
  return n;
}

test::GltfMaterial material(glm::vec4 base_colour, int image = -1, json extra = json::object()) {
  test::GltfMaterial m;
  m.base_colour = base_colour;
  m.base_colour_image = image;
  m.json = std::move(extra);
  return m;
}

GltfPrimitive triangle_primitive() {
  GltfPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  return p;
}

glm::vec3 world_min(const Model& m) { return glm::vec3(m.mesh.origin + glm::dvec3(m.mesh.bounds.min)); }
glm::vec3 world_max(const Model& m) { return glm::vec3(m.mesh.origin + glm::dvec3(m.mesh.bounds.max)); }

class EveryForm : public ::testing::TestWithParam<GltfForm> {};

TEST_P(EveryForm, CubeImportsWithItsTrianglesNormalsAndBounds) {
  const Model m = import_files(test::write_gltf(cube_document(), GetParam()));
  EXPECT_EQ(m.mesh.triangle_count(), 12u);
  EXPECT_EQ(m.mesh.positions.size(), 24u);  // split at the hard edges
  EXPECT_NEAR(world_min(m).x, -1.0f, 1e-6f);
  EXPECT_NEAR(world_max(m).z, 1.0f, 1e-6f);
  for (std::size_t i = 0; i < m.mesh.positions.size(); ++i) {
    // Each face's own normal, as the file gives it, points away from the centre.
    EXPECT_GT(glm::dot(m.mesh.normals[i], m.mesh.positions[i] - m.mesh.bounds.centre()), 0.0f);
  }
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
}

INSTANTIATE_TEST_SUITE_P(Gltf, EveryForm,
                         ::testing::Values(GltfForm::Glb, GltfForm::SeparateFiles, GltfForm::DataUris));

TEST(GltfImport, IsRecognisedByContentWhateverItsName) {
  auto files = test::write_gltf(cube_document(), GltfForm::Glb);
  files[0].first = "download.dat";
  EXPECT_EQ(import_files(files).mesh.triangle_count(), 12u);
  auto text = test::write_gltf(cube_document(), GltfForm::DataUris);
  text[0].first = "scene.json";
  EXPECT_EQ(import_files(text).mesh.triangle_count(), 12u);
}

TEST(GltfImport, NodeTransformsAreBakedInDoublePrecision) {
  GltfDocument doc;
  doc.meshes = {{triangle_primitive()}};
  // parent: far away; child: scaled by 2 and turned a quarter about +Z.
  const double half = std::sqrt(0.5);
  doc.nodes = {node(-1, {1}), node(0)};
  doc.nodes[0].translation = glm::dvec3(1e7, 0, 0);
  doc.nodes[1].rotation = glm::dvec4(0, 0, half, half);
  doc.nodes[1].scale = glm::dvec3(2, 2, 2);
  doc.scene_roots = {0};
  const Model trs = import_files(test::write_gltf(doc, GltfForm::Glb));
  // (1,0,0) -> (0,2,0) and (0,1,0) -> (-2,0,0), then 1e7 along x.
  EXPECT_DOUBLE_EQ(trs.mesh.origin.x + trs.mesh.bounds.min.x, 1e7 - 2.0);
  EXPECT_NEAR(trs.mesh.origin.y + trs.mesh.bounds.max.y, 2.0, 1e-6);
  EXPECT_NEAR(trs.mesh.bounds.max.x - trs.mesh.bounds.min.x, 2.0f, 1e-6f);  // float precision kept far away

  // The same placement as one matrix (column-major).
  doc.nodes = {node(0)};
  doc.nodes[0].matrix = std::array<double, 16>{0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 1e7, 0, 0, 1};
  const Model matrix = import_files(test::write_gltf(doc, GltfForm::Glb));
  EXPECT_NEAR(matrix.mesh.origin.x + matrix.mesh.bounds.min.x, 1e7 - 2.0, 1e-6);
  EXPECT_NEAR(matrix.mesh.origin.y + matrix.mesh.bounds.max.y, 2.0, 1e-6);
}

TEST(GltfImport, AMirroringTransformKeepsTheFacesTurnedOutward) {
  GltfDocument doc;
  doc.meshes = {{triangle_primitive()}};  // counter-clockwise seen from +z, no normals
  doc.nodes = {node(0)};
  doc.nodes[0].scale = glm::dvec3(-1, 1, 1);
  doc.scene_roots = {0};
  const Model m = import_files(test::write_gltf(doc, GltfForm::Glb));
  ASSERT_EQ(m.mesh.triangle_count(), 1u);
  EXPECT_GT(m.mesh.normals[0].z, 0.99f);
}

TEST(GltfImport, StripsAndFansBecomeTrianglesAndPointsAreNamed) {
  GltfPrimitive strip;
  strip.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  strip.mode = 5;
  GltfPrimitive fan;
  for (int i = 0; i < 6; ++i) {
    const double a = i * 0.5;
    fan.positions.emplace_back(3 + std::cos(a), std::sin(a), 0);
  }
  fan.mode = 6;
  GltfPrimitive points = triangle_primitive();
  points.mode = 0;
  GltfDocument doc;
  doc.meshes = {{strip, fan, points}};
  const Model m = import_files(test::write_gltf(doc, GltfForm::Glb));
  EXPECT_EQ(m.mesh.triangle_count(), 2u + 4u);
  for (const glm::vec3& n : m.mesh.normals) EXPECT_GT(n.z, 0.99f) << "a strip triangle is wound backwards";
  EXPECT_TRUE(has_warning(m, "point or line primitives are not drawn")) << warnings_of(m);
}

TEST(GltfImport, VertexColoursAreLinearInTheFileAndSrgbEncodedInTheMesh) {
  GltfPrimitive p = triangle_primitive();
  p.colours = {{0.5f, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 0.214f, 1}};
  GltfDocument doc;
  doc.meshes = {{p}};
  const Model m = import_files(test::write_gltf(doc, GltfForm::Glb));
  ASSERT_TRUE(m.has_vertex_colors);
  ASSERT_EQ(m.mesh.colors.size(), 3u);
  bool saw_half = false;
  for (const glm::vec3& c : m.mesh.colors) saw_half = saw_half || std::abs(c.r - 0.7354f) < 1e-3f;
  EXPECT_TRUE(saw_half) << "linear 0.5 is sRGB 0.735";
  // The material does not darken the colours.
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1.0f));
}

TEST(GltfImport, SeveralPrimitivesKeepTheirOwnMaterials) {
  GltfPrimitive a = triangle_primitive();
  a.material = 0;
  GltfPrimitive b = triangle_primitive();
  for (auto& p : b.positions) p.z += 1.0f;
  b.material = 1;
  GltfDocument doc;
  doc.meshes = {{a, b}};
  doc.materials = {material({1, 0, 0, 1}), material({0, 0, 1, 1})};
  const Model m = import_files(test::write_gltf(doc, GltfForm::SeparateFiles));
  ASSERT_EQ(m.mesh.submeshes.size(), 2u);
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1, 0, 0));
  EXPECT_EQ(m.materials[1].diffuse, glm::vec3(0, 0, 1));
}

TEST(GltfImport, EmissiveIsAddedToTheBaseColour) {
  GltfDocument doc;
  doc.meshes = {{triangle_primitive()}};
  doc.meshes[0][0].material = 0;
  doc.materials = {material({0.5f, 0.1f, 0.1f, 1}, -1, {{"emissiveFactor", {0.75, 0.2, 0}}})};
  const Model m = import_files(test::write_gltf(doc, GltfForm::Glb));
  EXPECT_NEAR(m.materials[0].diffuse.r, 1.0f, 1e-6f);
  EXPECT_NEAR(m.materials[0].diffuse.g, 0.3f, 1e-6f);
  EXPECT_NEAR(m.materials[0].diffuse.b, 0.1f, 1e-6f);
}

GltfDocument textured_cube(const std::string& png) {
  GltfDocument doc = cube_document();
  doc.meshes[0][0].material = 0;
  doc.images = {{png, "image/png", "skin.png"}};
  doc.materials = {material(glm::vec4(1.0f), 0)};
  return doc;
}

TEST(GltfImport, GlbCarriesItsImageInABufferView) {
  const Model m = import_files(test::write_gltf(textured_cube(tiny_png(10, 200, 30)), GltfForm::Glb));
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].rgba[1], 200);
  EXPECT_EQ(m.textures[0].color_space, ColorSpace::Srgb);
  EXPECT_EQ(m.materials[0].diffuse_texture, 0);
}

TEST(GltfImport, ImageFilesBesideTheGltfAreRead) {
  const Model m = import_files(test::write_gltf(textured_cube(tiny_png(10, 200, 30)), GltfForm::SeparateFiles));
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].path, "skin.png");
}

TEST(GltfImport, ATextureMayBeADataUri) {
  auto parts = test::build_gltf(textured_cube(tiny_png(10, 200, 30)));
  parts.json["images"][0] = {{"uri", test::data_uri(tiny_png(250, 5, 5), "image/png")}};
  const Model m = import_files(test::pack_gltf(parts, GltfForm::DataUris));
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].rgba[0], 250);
}

TEST(GltfImport, AnImageThatCannotBeDecodedLeavesOnlyItsMaterialUntextured) {
  const Model m = import_files(test::write_gltf(textured_cube("not an image at all"), GltfForm::Glb));
  EXPECT_EQ(m.mesh.triangle_count(), 12u);
  EXPECT_EQ(m.materials[0].diffuse_texture, -1);
  EXPECT_TRUE(has_warning(m, "cannot be used")) << warnings_of(m);
}

TEST(GltfImport, WebpImagesOfExtTextureWebpAreDecoded) {
  const std::vector<std::uint8_t> rgba = {20, 40, 220, 255, 20, 40, 220, 255, 20, 40, 220, 255, 20, 40, 220, 255};
  std::uint8_t* encoded = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(rgba.data(), 2, 2, 8, &encoded);
  ASSERT_GT(size, 0u);
  const std::string webp(reinterpret_cast<const char*>(encoded), size);
  WebPFree(encoded);
  auto parts = test::build_gltf(textured_cube(tiny_png(1, 1, 1)));
  // The WebP image is preferred; the PNG stays as the fallback.
  parts.json["images"][0] = {{"uri", test::data_uri(tiny_png(1, 1, 1), "image/png")}};
  parts.json["images"][1] = {{"uri", test::data_uri(webp, "image/webp")}};
  parts.json["textures"][0]["extensions"] = {{"EXT_texture_webp", {{"source", 1}}}};
  parts.json["extensionsUsed"] = {"EXT_texture_webp"};
  parts.json["extensionsRequired"] = {"EXT_texture_webp"};
  const Model m = import_files(test::pack_gltf(parts, GltfForm::Glb));
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].rgba[2], 220);
}

TEST(GltfImport, KtxOnlyTexturesAreNamedAndLeftOut) {
  auto parts = test::build_gltf(textured_cube(tiny_png(1, 1, 1)));
  parts.json["textures"][0] = {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}};
  const Model m = import_files(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_EQ(m.materials[0].diffuse_texture, -1);
  EXPECT_TRUE(has_warning(m, "KTX2/Basis")) << warnings_of(m);
}

TEST(GltfImport, TextureTransformMovesTheCoordinates) {
  GltfDocument doc = textured_cube(tiny_png(1, 1, 1));
  const Model plain = import_files(test::write_gltf(doc, GltfForm::Glb));
  doc.materials[0].json = {
      {"pbrMetallicRoughness",
       {{"baseColorTexture",
         {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"scale", {0.5, 0.5}}}}}}}}}}};
  const Model moved = import_files(test::write_gltf(doc, GltfForm::Glb));
  ASSERT_EQ(plain.mesh.texcoords.size(), moved.mesh.texcoords.size());
  for (std::size_t i = 0; i < plain.mesh.texcoords.size(); ++i) {
    const glm::vec2 p = plain.mesh.texcoords[i];
    // u' = 0.5 + 0.5 u; v (glTF, down) = 0.5 v, so the mesh's v (up) = 1 - 0.5 (1 - v_mesh).
    EXPECT_NEAR(moved.mesh.texcoords[i].x, 0.5f + 0.5f * p.x, 1e-6f);
    EXPECT_NEAR(moved.mesh.texcoords[i].y, 1.0f - 0.5f * (1.0f - p.y), 1e-6f);
  }
}

TEST(GltfImport, QuantizedAndSparseAccessorsAreRead) {
  auto parts = test::build_gltf(cube_document());
  // Positions as normalised shorts (KHR_mesh_quantization) in a new view.
  const auto& cube = cube_primitive();
  std::string shorts;
  for (const glm::vec3& p : cube.positions) {
    for (int c = 0; c < 3; ++c) {
      const auto v = static_cast<std::int16_t>(std::lround(p[c] * 0.5f * 32767.0f));
      shorts.append(reinterpret_cast<const char*>(&v), 2);
    }
    shorts.append(2, '\0');  // stride 8
  }
  const std::size_t offset = parts.bin.size();
  parts.bin += shorts;
  parts.json["buffers"][0]["byteLength"] = parts.bin.size();
  parts.json["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", shorts.size()}, {"byteStride", 8}});
  // Sparse: vertex 0 is moved to (0, 0, 1), in the accessor's own normalised shorts.
  const std::size_t sparse_at = parts.bin.size();
  const std::uint16_t index = 0;
  const std::int16_t moved[3] = {0, 0, 32767};
  parts.bin.append(reinterpret_cast<const char*>(&index), 2);
  parts.bin.append(2, '\0');
  parts.bin.append(reinterpret_cast<const char*>(moved), 6);
  parts.bin.append(2, '\0');
  parts.json["buffers"][0]["byteLength"] = parts.bin.size();
  parts.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", sparse_at}, {"byteLength", 2}});
  parts.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", sparse_at + 4}, {"byteLength", 6}});
  const auto views = parts.json["bufferViews"].size();
  json& position = parts.json["accessors"][0];
  position = {{"bufferView", views - 3},
              {"componentType", 5122},
              {"normalized", true},
              {"count", cube.positions.size()},
              {"type", "VEC3"},
              {"min", {-1, -1, -1}},
              {"max", {1, 1, 1}},
              {"sparse",
               {{"count", 1},
                {"indices", {{"bufferView", views - 2}, {"componentType", 5123}}},
                {"values", {{"bufferView", views - 1}}}}}};
  parts.json["extensionsUsed"] = {"KHR_mesh_quantization"};
  parts.json["extensionsRequired"] = {"KHR_mesh_quantization"};
  const Model m = import_files(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NEAR(world_min(m).x, -0.5f, 1e-4f);
  EXPECT_NEAR(world_max(m).z, 1.0f, 1e-6f);  // 0.5 without the sparse substitution
}

// A unit quad facing +Z with texture coordinates, and the tangent the
// file gives every corner (none when `tangent` is unset).
GltfDocument quad_document(std::optional<glm::vec4> tangent) {
  GltfPrimitive quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals.assign(4, {0, 0, 1});
  quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  if (tangent) quad.tangents.assign(4, *tangent);
  quad.indices = {0, 1, 2, 0, 2, 3};
  GltfDocument doc;
  doc.meshes = {{quad}};
  return doc;
}

TEST(GltfImport, TheFilesTangentsAreKeptAndTurnWithTheirNode) {
  // Along +y, left-handed: not what the texture coordinates would give
  // (+x), so a derived tangent cannot pass for it.
  const glm::vec4 given(0, 2, 0, -1);
  const Model derived = import_files(test::write_gltf(quad_document(std::nullopt), GltfForm::Glb));
  for (const glm::vec4& t : derived.mesh.tangents) EXPECT_NEAR(std::abs(t.x), 1.0f, 1e-6f);
  const Model kept = import_files(test::write_gltf(quad_document(given), GltfForm::Glb));
  ASSERT_EQ(kept.mesh.tangents.size(), 4u);
  for (const glm::vec4& t : kept.mesh.tangents) {
    EXPECT_NEAR(t.x, 0.0f, 1e-6f);
    EXPECT_NEAR(t.y, 1.0f, 1e-6f);  // unit length
    EXPECT_EQ(t.w, -1.0f);
  }

  // A node turned a quarter about z and mirrored in x: the tangent turns
  // with it, and the mirror changes its hand.
  GltfDocument turned = quad_document(given);
  test::GltfNode node;
  node.mesh = 0;
  node.rotation = glm::dvec4(0, 0, std::sqrt(0.5), std::sqrt(0.5));
  node.scale = glm::dvec3(-1, 1, 1);
  turned.nodes = {node};
  turned.scene_roots = {0};
  const Model moved = import_files(test::write_gltf(turned, GltfForm::Glb));
  for (const glm::vec4& t : moved.mesh.tangents) {
    // Scale first: (0,1,0) stays; the quarter turn takes +y to -x.
    EXPECT_NEAR(t.x, -1.0f, 1e-6f);
    EXPECT_NEAR(t.y, 0.0f, 1e-6f);
    EXPECT_EQ(t.w, 1.0f);
  }
}

TEST(GltfImport, AnUnusableTangentFallsBackToTheDerivedOne) {
  const Model zero = import_files(test::write_gltf(quad_document(glm::vec4(0, 0, 0, 1)), GltfForm::Glb));
  const Model no_hand = import_files(test::write_gltf(quad_document(glm::vec4(0, 1, 0, 0)), GltfForm::Glb));
  const Model derived = import_files(test::write_gltf(quad_document(std::nullopt), GltfForm::Glb));
  EXPECT_EQ(zero.mesh.tangents, derived.mesh.tangents);
  EXPECT_EQ(no_hand.mesh.tangents, derived.mesh.tangents);
}

// glTF 2.0 §3.7.2.1: a primitive without NORMAL is flat-shaded, whatever
// the angle between its faces. The cube comes out as the OBJ cube without
// normals does (its 90° edges are sharp by angle too): six flat faces of
// four corners each.
TEST(GltfImport, MissingNormalsAreFlat) {
  GltfPrimitive p = cube_primitive();
  p.normals.clear();
  p.texcoords.clear();
  GltfDocument doc;
  doc.meshes = {{p}};
  const Model gltf = import_files(test::write_gltf(doc, GltfForm::Glb));
  const std::string obj =
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n";
  const Model reference = import_bundle(make_bundle({{"cube.obj", obj}}));
  for (std::size_t t = 0; t < gltf.mesh.indices.size(); t += 3) {
    const glm::dvec3 face = triangle_normal(glm::dvec3(gltf.mesh.positions[gltf.mesh.indices[t]]),
                                            glm::dvec3(gltf.mesh.positions[gltf.mesh.indices[t + 1]]),
                                            glm::dvec3(gltf.mesh.positions[gltf.mesh.indices[t + 2]]));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(glm::dot(glm::dvec3(gltf.mesh.normals[gltf.mesh.indices[t + k]]), face), 1.0, 1e-6);
    }
  }
  EXPECT_EQ(gltf.mesh.positions.size(), 24u);
  EXPECT_EQ(gltf.mesh.positions.size(), reference.mesh.positions.size());
}

// A sphere: the OBJ without normals is smooth by angle, the glTF flat.
TEST(GltfImport, MissingNormalsAreFlatEvenWhereObjWouldSmooth) {
  GltfPrimitive p;
  const int rings = 12, segments = 24;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {
      const float th = 3.14159265f * r / rings, ph = 6.2831853f * s / segments;
      p.positions.emplace_back(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const auto a = static_cast<std::uint32_t>(r * (segments + 1) + s), b = a + 1,
                 c = a + static_cast<std::uint32_t>(segments + 1), d = c + 1;
      p.indices.insert(p.indices.end(), {a, b, c, b, d, c});
    }
  }
  GltfDocument doc;
  doc.meshes = {{p}};
  const Model gltf = import_files(test::write_gltf(doc, GltfForm::Glb));
  std::size_t flat = 0, slivers = 0;
  for (std::size_t t = 0; t < gltf.mesh.indices.size(); t += 3) {
    const glm::dvec3 face = triangle_normal(glm::dvec3(gltf.mesh.positions[gltf.mesh.indices[t]]),
                                            glm::dvec3(gltf.mesh.positions[gltf.mesh.indices[t + 1]]),
                                            glm::dvec3(gltf.mesh.positions[gltf.mesh.indices[t + 2]]));
    // The pole's corners are a hair apart (sin π in floats): the slivers
    // there have no normal of their own and take their neighbours'.
    if (glm::length(face) < 0.5) {
      ++slivers;
      EXPECT_LT(gltf.mesh.normals[gltf.mesh.indices[t]].y, -0.9f) << "the south pole's normal points down";
      continue;
    }
    // Within 1°: thin triangles near the poles are computed in floats; a
    // smoothed normal there would turn by half a segment, 7.5°.
    if (glm::dot(glm::dvec3(gltf.mesh.normals[gltf.mesh.indices[t]]), face) > std::cos(glm::radians(1.0))) ++flat;
  }
  EXPECT_EQ(flat + slivers, gltf.mesh.triangle_count());
  EXPECT_LT(slivers, 30u);
}

TEST(GltfImport, IgnoredFeaturesAreNamedInTheWarnings) {
  auto parts = test::build_gltf(textured_cube(tiny_png(1, 1, 1)));
  parts.json["materials"][0]["alphaMode"] = "BLEND";
  parts.json["animations"] = json::array({{{"channels", json::array()}, {"samplers", json::array()}}});
  parts.json["extensionsUsed"] = {"KHR_lights_punctual"};
  const Model m = import_files(test::pack_gltf(parts, GltfForm::Glb));
  // BLEND is drawn blended now, so nothing about it is left unread.
  EXPECT_FALSE(has_warning(m, "BLEND")) << warnings_of(m);
  EXPECT_EQ(m.materials[0].alpha_mode, AlphaMode::Blend);
  EXPECT_TRUE(has_warning(m, "KHR_lights_punctual")) << warnings_of(m);
  // Animations are read now (an empty one is a clip of no length).
  EXPECT_FALSE(has_warning(m, "animations")) << warnings_of(m);
  ASSERT_TRUE(m.rig);
  EXPECT_EQ(m.rig->clips.size(), 1u);
}

TEST(GltfImport, MaskMaterialsKeepTheirCutoffAndUnlitOnesAreMarked) {
  auto parts = test::build_gltf(textured_cube(tiny_png(1, 1, 1)));
  parts.json["materials"][0]["alphaMode"] = "MASK";
  parts.json["materials"][0]["alphaCutoff"] = 0.3;
  parts.json["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1, 1, 1, 0.75};
  parts.json["materials"][0]["extensions"] = {{"KHR_materials_unlit", json::object()}};
  parts.json["extensionsUsed"] = {"KHR_materials_unlit"};
  const Model m = import_files(test::pack_gltf(parts, GltfForm::Glb));
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_FLOAT_EQ(m.materials[0].alpha_cutoff, 0.3f);
  EXPECT_FLOAT_EQ(m.materials[0].opacity, 0.75f);
  EXPECT_TRUE(m.materials[0].unlit);
  EXPECT_FALSE(has_warning(m, "alpha")) << warnings_of(m);
  EXPECT_FALSE(has_warning(m, "unlit")) << warnings_of(m);

  EXPECT_EQ(m.materials[0].alpha_mode, AlphaMode::Mask);

  // MASK without a cutoff takes glTF's 0.5; OPAQUE cuts nothing.
  parts.json["materials"][0].erase("alphaCutoff");
  EXPECT_FLOAT_EQ(import_files(test::pack_gltf(parts, GltfForm::Glb)).materials[0].alpha_cutoff, 0.5f);
  parts.json["materials"][0]["alphaMode"] = "OPAQUE";
  parts.json["materials"][0].erase("extensions");
  const Model opaque = import_files(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_EQ(opaque.materials[0].alpha_mode, AlphaMode::Opaque);
  EXPECT_FALSE(opaque.materials[0].unlit);
}

TEST(GltfImport, ASceneMayBePickedByIndex) {
  auto parts = test::build_gltf(cube_document());
  parts.json["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 3}}}}});
  parts.json["nodes"].push_back({{"mesh", 1}, {"translation", {100, 0, 0}}});
  parts.json["scenes"].push_back({{"nodes", {1}}});
  const Bundle bundle = make_bundle(test::pack_gltf(parts, GltfForm::Glb));
  const Model first = import_gltf_bundle(bundle, "model.glb");
  EXPECT_NEAR(world_max(first).x, 1.0f, 1e-6f);
  EXPECT_TRUE(has_warning(first, "2 scenes")) << warnings_of(first);
  ImportChoices scene_1;
  scene_1.gltf_scene = 1;
  ImportChoices scene_2;
  scene_2.gltf_scene = 2;
  const Model second = import_gltf_bundle(bundle, "model.glb", {}, scene_1);
  EXPECT_NEAR(world_max(second).x, 101.0f, 1e-6f);
  EXPECT_THROW(import_gltf_bundle(bundle, "model.glb", {}, scene_2), ImportError);
}

TEST(GltfImport, ANodeCycleIsDrawnOnceNotForever) {
  auto parts = test::build_gltf(cube_document());
  parts.json["nodes"][0]["children"] = {0};
  const Model m = import_files(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_EQ(m.mesh.triangle_count(), 12u);
  EXPECT_TRUE(has_warning(m, "reached twice")) << warnings_of(m);
}

// --- broken and hostile files ---

TEST(GltfMalformed, TruncatedChunkIsRefused) {
  const std::string glb = test::write_gltf(cube_document(), GltfForm::Glb)[0].second;
  const std::string cut = glb.substr(0, glb.size() - 100);
  EXPECT_NE(import_error({{"model.glb", cut}}).find("truncated"), std::string::npos);
  // A chunk length past the file's end, with the header's total mended.
  std::string lying = glb;
  lying[12] = '\xff';
  lying[13] = '\xff';
  EXPECT_NE(import_error({{"model.glb", lying}}).find("not a valid glTF binary"), std::string::npos);
}

TEST(GltfMalformed, AccessorPastItsBufferViewIsRefused) {
  auto parts = test::build_gltf(cube_document());
  parts.json["accessors"][0]["count"] = 25;
  EXPECT_NE(import_error(test::pack_gltf(parts, GltfForm::Glb)).find("reaches past the end of buffer view"),
            std::string::npos);
  parts = test::build_gltf(cube_document());
  parts.json["bufferViews"][0]["byteLength"] = 1 << 20;
  EXPECT_NE(import_error(test::pack_gltf(parts, GltfForm::Glb)).find("reaches past the end of buffer"),
            std::string::npos);
}

TEST(GltfMalformed, IndexPastTheVerticesIsRefusedNamingThePrimitive) {
  GltfDocument doc = cube_document();
  doc.meshes[0][0].indices[5] = 24;
  const std::string error = import_error(test::write_gltf(doc, GltfForm::Glb));
  EXPECT_NE(error.find("mesh 0 primitive 0 has the index 24"), std::string::npos) << error;
}

TEST(GltfMalformed, APrimitiveWithoutPositionsIsRefusedNamingIt) {
  auto parts = test::build_gltf(cube_document());
  parts.json["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  const std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("mesh 0 primitive 0 has no POSITION"), std::string::npos) << error;
}

TEST(GltfMalformed, UrisThatLeaveTheBundleAreRefused) {
  for (const std::string uri : {"../model.bin", "sub/../../model.bin", "/etc/passwd", "http://example.com/model.bin",
                                "file:///etc/passwd", "C:/model.bin", "%2E%2E/model.bin"}) {
    auto files = test::write_gltf(cube_document(), GltfForm::SeparateFiles);
    json doc = json::parse(files[0].second);
    doc["buffers"][0]["uri"] = uri;
    files[0].second = doc.dump();
    const std::string error = import_error(files);
    EXPECT_NE(error.find("may only name files of the upload"), std::string::npos) << uri << ": " << error;
  }
  auto files = test::write_gltf(textured_cube(tiny_png(1, 1, 1)), GltfForm::SeparateFiles);
  json doc = json::parse(files[1].second);
  doc["images"][0]["uri"] = "../../secret.png";
  files[1].second = doc.dump();
  EXPECT_NE(import_error(files).find("image 0 has the URI"), std::string::npos);
}

TEST(GltfMalformed, AMissingBufferFileIsNamed) {
  auto files = test::write_gltf(cube_document(), GltfForm::SeparateFiles);
  files.pop_back();  // model.bin
  EXPECT_NE(import_error(files).find("'model.bin', which is not in the upload"), std::string::npos);
}

TEST(GltfMalformed, AHugeCountInATinyFileIsRefusedBeforeAllocating) {
  auto parts = test::build_gltf(cube_document());
  parts.json["accessors"][0]["count"] = 2'000'000'000;
  parts.json["accessors"][3]["count"] = 2'000'000'000;
  const auto files = test::pack_gltf(parts, GltfForm::Glb);
  ImportLimits limits;
  limits.max_vertices = 1'000'000;
  limits.max_triangles = 1'000'000;
  EXPECT_NE(import_error(files, limits).find("limit --max-vertices"), std::string::npos);
  // Without limits (a stored model), the range check refuses it first.
  EXPECT_NE(import_error(files).find("reaches past the end"), std::string::npos);
}

TEST(GltfMalformed, RequiredExtensionsNotReadAreNamed) {
  auto parts = test::build_gltf(cube_document());
  parts.json["extensionsUsed"] = {"KHR_materials_variants"};
  parts.json["extensionsRequired"] = {"KHR_materials_variants"};
  const std::string error = import_error(test::pack_gltf(parts, GltfForm::Glb));
  EXPECT_NE(error.find("requires the glTF extension 'KHR_materials_variants'"), std::string::npos) << error;
  // The answer lists what is read, the compression extensions among it.
  EXPECT_NE(error.find("EXT_meshopt_compression"), std::string::npos) << error;
  EXPECT_NE(error.find("KHR_draco_mesh_compression"), std::string::npos) << error;
}

TEST(GltfMalformed, NotJsonOrNotVersionTwoIsRefused) {
  EXPECT_NE(import_error({{"model.gltf", "{\"asset\": {\"version\": \"1.0\"}}"}}).find("only 2.x"), std::string::npos);
  EXPECT_NE(import_error({{"model.gltf", "{\"asset\": [1, 2"}}).find("not valid glTF JSON"), std::string::npos);
  EXPECT_NE(import_error({{"model.glb", "glTF\x02"}}).find("not a valid glTF binary"), std::string::npos);
}

// --- twins of the shared OBJ models ---

class SharedTwin : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(SharedTwin, ImportsLikeItsObj) {
  TOOND_REQUIRE_SHARED_MODELS();
  const auto [folder, obj] = GetParam();
  const Bundle bundle = test_checks::shared_model_bundle(folder);
  const Model reference = import_obj_bundle(bundle);
  const Model twin = import_files(test::write_gltf(test::gltf_twin(reference, bundle), GltfForm::Glb));
  EXPECT_EQ(twin.mesh.triangle_count(), reference.mesh.triangle_count()) << obj;
  EXPECT_NEAR(glm::distance(world_min(twin), world_min(reference)), 0.0f, 1e-4f);
  EXPECT_NEAR(glm::distance(world_max(twin), world_max(reference)), 0.0f, 1e-4f);
  ASSERT_EQ(twin.materials.size(), reference.materials.size());
  for (std::size_t i = 0; i < twin.materials.size(); ++i) {
    EXPECT_EQ(twin.materials[i].diffuse, reference.materials[i].diffuse);
    EXPECT_EQ(twin.materials[i].diffuse_texture >= 0, reference.materials[i].diffuse_texture >= 0);
    EXPECT_EQ(twin.materials[i].normal_texture >= 0, reference.materials[i].normal_texture >= 0);
  }
  EXPECT_EQ(twin.textures.size(), reference.textures.size());
}

INSTANTIATE_TEST_SUITE_P(Gltf, SharedTwin,
                         ::testing::Values(std::make_pair("spot", "spot.obj"),
                                           std::make_pair("kenney-cube-pet-dog", "animal-dog.obj"),
                                           std::make_pair("windmill", "windmill.obj")));

}  // namespace
}  // namespace toond::scene
