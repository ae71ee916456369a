#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "model_checks.h"
#include "obj_text/obj_text.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/reading/import_error.h"
#include "scene/reading/texture_decode.h"
#include "support/shared_models.h"

namespace toond::scene {
namespace {

using obj_text::material_alias;
using obj_text::ObjTextFindings;
using obj_text::prepare_obj_text;
using test_checks::bundle_from_folder;
using test_checks::expect_import_error;
using test_checks::expect_well_formed;
using test_checks::has_warning;
using test_checks::make_bundle;
using test_checks::tiny_png;
using test_checks::warnings_of;

// Quads, positions only, the cube from 0 to 1.
const std::string kQuadCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";

// Normals by angle: the cube's faces meet at 90°, more than the default
// 30°, so each face keeps its own four corners and its own normal.
TEST(ObjImport, QuadsAreTriangulatedAndMissingNormalsComputedByAngle) {
  const Model m = import_obj_bundle(make_bundle({{"cube.obj", kQuadCube}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 12u);
  EXPECT_EQ(m.mesh.positions.size(), 24u);
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(0.8f));
  EXPECT_EQ(m.materials[0].normal_texture, -1);
  EXPECT_EQ(m.materials[0].specular, glm::vec3(0.0f));
  EXPECT_EQ(m.materials[0].shininess, 32.0f);
  EXPECT_FALSE(m.has_vertex_colors);
  EXPECT_TRUE(m.mesh.colors.empty());
  // Recentred on the bounds centre: positions are +-0.5, the centre is in origin.
  EXPECT_EQ(m.mesh.origin, glm::dvec3(0.5));
  EXPECT_EQ(m.mesh.bounds.min, glm::vec3(-0.5f));
  EXPECT_EQ(m.mesh.bounds.max, glm::vec3(0.5f));
  for (std::size_t v = 0; v < m.mesh.positions.size(); ++v) EXPECT_EQ(m.mesh.texcoords[v], glm::vec2(0.0f));
  // Every triangle is wound counter-clockwise seen from outside, and each
  // corner's normal is its face's.
  for (std::size_t t = 0; t < m.mesh.indices.size(); t += 3) {
    const glm::dvec3 a = m.mesh.positions[m.mesh.indices[t]];
    const glm::dvec3 b = m.mesh.positions[m.mesh.indices[t + 1]];
    const glm::dvec3 c = m.mesh.positions[m.mesh.indices[t + 2]];
    const glm::dvec3 face = triangle_normal(a, b, c);
    EXPECT_GT(glm::dot(face, (a + b + c) / 3.0), 0.0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(glm::dot(glm::dvec3(m.mesh.normals[m.mesh.indices[t + k]]), face), 1.0, 1e-6) << t;
    }
  }
}

// `smooth_angle` 180 smooths every edge: the cube's 8 corners shared, each
// normal along its diagonal (what toond did before normals by angle).
TEST(ObjImport, ASmoothAngleOf180SmoothsEveryEdge) {
  ImportChoices smooth;
  smooth.smooth_angle = 180;
  const Model m = import_obj_bundle(make_bundle({{"cube.obj", kQuadCube}}), {}, smooth);
  ASSERT_EQ(m.mesh.positions.size(), 8u);
  for (std::size_t v = 0; v < 8; ++v) {
    EXPECT_NEAR(glm::dot(m.mesh.normals[v], glm::normalize(m.mesh.positions[v])), 1.0f, 1e-5f);
  }
}

// `up=z` turns a Z-up file so that its +Z is +Y: (x, y, z) → (x, z, −y).
TEST(ObjImport, UpZTurnsTheFileUpright) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 0 3\nvn 0 -1 0\nf 1//1 2//1 3//1\n";
  ImportChoices z_up;
  z_up.up = ImportChoices::Up::Z;
  const Model m = import_obj_bundle(make_bundle({{"tall.obj", obj}}), {}, z_up);
  EXPECT_NEAR(m.mesh.bounds.max.y - m.mesh.bounds.min.y, 3.0f, 1e-6f);
  EXPECT_NEAR(m.mesh.bounds.max.z - m.mesh.bounds.min.z, 0.0f, 1e-6f);
  for (const glm::vec3& n : m.mesh.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

TEST(ObjImport, FarFromOriginKeepsPrecision) {
  // A unit cube a thousand kilometres out, with millimetre detail: float
  // positions would lose it, recentred ones keep it.
  std::string obj;
  for (int i = 0; i < 8; ++i) {
    obj += "v " + std::to_string(1e6 + ((i & 1) ? 1.001 : 0.0)) + " " + std::to_string((i & 2) ? 1.0 : 0.0) + " " +
           std::to_string(-2e6 + ((i & 4) ? 1.0 : 0.0)) + "\n";
  }
  obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 5 7 3\nf 2 4 8 6\nf 3 7 8 4\nf 1 2 6 5\n";
  const Model m = import_obj_bundle(make_bundle({{"far.obj", obj}}));
  expect_well_formed(m);
  EXPECT_NEAR(m.mesh.origin.x, 1e6 + 0.5005, 1e-9);
  EXPECT_NEAR(m.mesh.origin.z, -2e6 + 0.5, 1e-9);
  EXPECT_NEAR(m.mesh.bounds.max.x - m.mesh.bounds.min.x, 1.001f, 1e-6f);
  EXPECT_NEAR(m.mesh.bounds.centre().x, 0.0f, 1e-6f);
}

TEST(ObjImport, HardEdgedCubeSplitsNormalsButSharesOutlineNormals) {
  const std::string obj =
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
      "vn 0 0 -1\nvn 0 0 1\nvn -1 0 0\nvn 1 0 0\nvn 0 1 0\nvn 0 -1 0\n"
      "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 5//3 8//3 4//3\n"
      "f 2//4 3//4 7//4 6//4\nf 4//5 8//5 7//5 3//5\nf 1//6 2//6 6//6 5//6\n";
  const Model m = import_obj_bundle(make_bundle({{"box.obj", obj}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.positions.size(), 24u);  // (position, normal) pairs
  EXPECT_EQ(m.mesh.triangle_count(), 12u);
  for (std::size_t v = 0; v < 24; ++v) {
    const glm::vec3 n = m.mesh.normals[v];
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);  // a face normal
    // The corner diagonal, mitred: each face plane moves out one unit.
    EXPECT_NEAR(glm::dot(glm::normalize(m.mesh.outline_normals[v]), glm::normalize(m.mesh.positions[v])), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(m.mesh.outline_normals[v], n), 1.0f, 1e-5f);
    for (std::size_t w = 0; w < 24; ++w) {
      if (m.mesh.positions[w] == m.mesh.positions[v]) {
        EXPECT_EQ(m.mesh.outline_normals[w], m.mesh.outline_normals[v]);
      }
    }
  }
}

TEST(ObjImport, VerticesAreDeduplicatedByTriple) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nvn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\nf 1/5/1 2/2/1 4/4/1\n";
  const Model m = import_obj_bundle(make_bundle({{"q.obj", obj}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 3u);
  EXPECT_EQ(m.mesh.positions.size(), 5u);  // 1/5/1 is a new triple
  std::set<std::pair<float, float>> uvs;
  for (const auto& uv : m.mesh.texcoords) uvs.insert({uv.x, uv.y});
  EXPECT_TRUE(uvs.count({0.5f, 0.5f}));
  for (const auto& n : m.mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(ObjImport, MaterialsBecomeSubmeshes) {
  const std::string obj =
      "mtllib two.mtl\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
      "o first\nusemtl red\nf 1 2 3\ng second\nusemtl blue\nf 2 5 6\nf 2 6 3\n"
      "usemtl red\nf 1 3 4\no third\nusemtl nowhere\nf 4 1 6\n";
  const std::string mtl = "newmtl red\nKd 1 0 0\n\nnewmtl blue\nKd 0 0 1\n\nnewmtl unused\nKd 0 1 0\n";
  const Model m = import_obj_bundle(make_bundle({{"m.obj", obj}, {"two.mtl", mtl}}));
  expect_well_formed(m);
  ASSERT_EQ(m.materials.size(), 3u);  // red, blue, default; "unused" left out
  EXPECT_EQ(m.materials[0].name, "red");
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1, 0, 0));
  EXPECT_EQ(m.materials[1].name, "blue");
  EXPECT_EQ(m.materials[1].diffuse, glm::vec3(0, 0, 1));
  EXPECT_EQ(m.materials[2].diffuse, glm::vec3(0.8f));
  ASSERT_EQ(m.mesh.submeshes.size(), 3u);
  EXPECT_EQ(m.mesh.submeshes[0].material, 0);
  EXPECT_EQ(m.mesh.submeshes[0].index_count, 6u);
  EXPECT_EQ(m.mesh.submeshes[1].material, 1);
  EXPECT_EQ(m.mesh.submeshes[1].index_count, 6u);
  EXPECT_EQ(m.mesh.submeshes[2].material, 2);
  EXPECT_EQ(m.mesh.submeshes[2].index_count, 3u);
  EXPECT_TRUE(has_warning(m, "nowhere")) << warnings_of(m);
}

TEST(ObjImport, MaterialNamesWithBlanks) {
  const std::string obj = "mtllib ./spaces.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl  Hard Shiny  Plastic \nf 1 2 3\n";
  const std::string mtl = "newmtl Hard Shiny  Plastic\r\nKd 0.1 0.2 0.3\r\n";
  const Model m = import_obj_bundle(make_bundle({{"s.obj", obj}, {"spaces.mtl", mtl}}));
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].name, "Hard Shiny  Plastic");
  EXPECT_NEAR(m.materials[0].diffuse.z, 0.3f, 1e-6f);
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
}

TEST(ObjImport, TexturesResolveThroughTheBundleAndDecodeOnce) {
  const std::string obj =
      "mtllib Mats\\Look.MTL\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
      "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 2/2 4/1 3/3\n";
  // Relative to the MTL's folder, backslashes, other case, options before
  // the name; the second material names the same file differently.
  const std::string mtl =
      "newmtl a\nKd 0.5 0.5 0.5\nmap_Kd -bm 1 -s 1 1 1 ..\\Tex\\Wood.PNG\n"
      "newmtl b\nmap_Kd ../tex/wood.png\n";
  const Model m = import_obj_bundle(
      make_bundle({{"model.obj", obj}, {"mats/look.mtl", mtl}, {"tex/wood.png", tiny_png(200, 100, 50)}}));
  expect_well_formed(m);
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].path, "tex/wood.png");
  EXPECT_EQ(m.textures[0].width, 4);
  EXPECT_EQ(m.textures[0].height, 2);
  EXPECT_EQ(m.textures[0].rgba[0], 200);
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].diffuse_texture, 0);
  EXPECT_EQ(m.materials[1].diffuse_texture, 0);
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(0.5f));  // Kd given: kept as-is
  EXPECT_EQ(m.materials[1].diffuse, glm::vec3(1.0f));  // no Kd: the texture shows as painted
}

TEST(ObjImport, MissingOrBrokenTextureIsAWarning) {
  const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 2 4 3\n";
  const std::string mtl = "newmtl a\nKd 0.2 0.4 0.6\nmap_Kd gone.png\nnewmtl b\nKd 1 1 1\nmap_Kd broken.png\n";
  const Model m =
      import_obj_bundle(make_bundle({{"m.obj", obj}, {"m.mtl", mtl}, {"broken.png", "definitely not an image"}}));
  expect_well_formed(m);
  EXPECT_TRUE(m.textures.empty());
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].diffuse_texture, -1);
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(0.2f, 0.4f, 0.6f));
  EXPECT_EQ(m.materials[1].diffuse_texture, -1);
  EXPECT_TRUE(has_warning(m, "gone.png")) << warnings_of(m);
  EXPECT_TRUE(has_warning(m, "broken.png")) << warnings_of(m);
}

TEST(ObjImport, TextureFoundByFileNameWhenThePathIsForeign) {
  const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
  const std::string mtl = "newmtl a\nKd 1 1 1\nmap_Kd C:\\Users\\artist\\Desktop\\skin.png\n";
  const Model m = import_obj_bundle(make_bundle({{"m.obj", obj}, {"m.mtl", mtl}, {"skin.png", tiny_png(1, 2, 3)}}));
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].path, "skin.png");
  EXPECT_TRUE(has_warning(m, "file name")) << warnings_of(m);
}

TEST(ObjImport, MtllibLinesAreReadAsToonReadsThem) {
  const std::string tail = "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 2 4 3\n";
  const auto diffuse_of = [](const Model& m, const std::string& name) {
    for (const Material& material : m.materials) {
      if (material.name == name) return material.diffuse;
    }
    return glm::vec3(-1);
  };
  // Every library of a line, not just the first; a missing one is said.
  const Model several = import_obj_bundle(make_bundle({{"m.obj", "mtllib gone.mtl mats\\a.mtl my\\ b.mtl" + tail},
                                                       {"mats/a.mtl", "newmtl a\nKd 1 0 0\n"},
                                                       {"my b.mtl", "newmtl b\nKd 0 0 1\n"}}));
  EXPECT_EQ(diffuse_of(several, "a"), glm::vec3(1, 0, 0));
  EXPECT_EQ(diffuse_of(several, "b"), glm::vec3(0, 0, 1));
  EXPECT_TRUE(has_warning(several, "gone.mtl")) << warnings_of(several);
  // An unescaped blank inside one library's name.
  const Model spaced = import_obj_bundle(
      make_bundle({{"m.obj", "mtllib my model.mtl" + tail}, {"my model.mtl", "newmtl a\nKd 0 1 0\nnewmtl b\n"}}));
  EXPECT_EQ(diffuse_of(spaced, "a"), glm::vec3(0, 1, 0));
  EXPECT_TRUE(spaced.warnings.empty()) << warnings_of(spaced);
}

TEST(ObjImport, MissingMtlIsAWarning) {
  const std::string obj = "mtllib nothere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl skin\nf 1 2 3\n";
  const Model m = import_obj_bundle(make_bundle({{"m.obj", obj}}));
  expect_well_formed(m);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(0.8f));
  EXPECT_TRUE(has_warning(m, "nothere.mtl")) << warnings_of(m);
  // Said once, by the importer: the parser adds no warning of its own.
  std::size_t about_the_library = 0;
  for (const std::string& w : m.warnings)
    about_the_library += w.find("material file") != std::string::npos || w.find("nothere.mtl") != std::string::npos;
  EXPECT_EQ(about_the_library, 1u) << warnings_of(m);
}

// The OBJ importer alone, so that a bundle without an .obj is its refusal.
Model import_obj_only(const Bundle& bundle) { return import_obj_bundle(bundle); }

TEST(ObjImport, BadIndicesAreImportErrors) {
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
  expect_import_error(import_obj_only, make_bundle({{"bad.obj", verts + "f 1 2 9\n"}}), "bad.obj", "bad.obj");
  expect_import_error(import_obj_only, make_bundle({{"bad.obj", verts + "f 1 2 3 9\n"}}), "bad.obj", "does not exist");
  expect_import_error(import_obj_only, make_bundle({{"bad.obj", verts + "f 1 2 3 4 9\n"}}), "bad.obj",
                      "does not exist");
  expect_import_error(import_obj_only, make_bundle({{"bad.obj", verts + "f 1 2 -7\n"}}), "bad.obj", "does not exist");
  expect_import_error(import_obj_only, make_bundle({{"bad.obj", verts + "f 1 2 0\n"}}), "bad.obj", "bad.obj");
}

TEST(ObjImport, NonFinitePositionsAreImportErrorsWithLine) {
  const std::string obj = "# header\nv 0 0 0\nv 1 0 0\nv 1e999 1 0\nf 1 2 3\n";
  expect_import_error(import_obj_only, make_bundle({{"inf.obj", obj}}), "inf.obj", "line 4");
}

TEST(ObjImport, BundleMustHoldExactlyOneObj) {
  expect_import_error(import_obj_only, make_bundle({{"a.mtl", "newmtl a\n"}}), "", "no .obj");
  expect_import_error(import_obj_only, Bundle{}, "", "no .obj");
  try {
    import_obj_bundle(make_bundle({{"a.obj", kQuadCube}, {"sub/B.OBJ", kQuadCube}}));
    ADD_FAILURE() << "no ImportError";
  } catch (const ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("a.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sub/B.OBJ"), std::string::npos) << e.what();
  }
  // The extension is matched case-insensitively.
  EXPECT_EQ(import_obj_bundle(make_bundle({{"CUBE.Obj", kQuadCube}})).mesh.triangle_count(), 12u);
}

TEST(ObjImport, NothingToRenderIsAnImportError) {
  expect_import_error(import_obj_only, make_bundle({{"lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\np 1\n"}}),
                      "lines.obj", "no faces");
  expect_import_error(import_obj_only, make_bundle({{"flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n"}}),
                      "flat.obj", "no faces");
  expect_import_error(import_obj_only, make_bundle({{"empty.obj", ""}}), "empty.obj", "no faces");
}

TEST(ObjImport, DegenerateTrianglesAreDroppedWithAWarning) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 3 3 1\n";
  const Model m = import_obj_bundle(make_bundle({{"d.obj", obj}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 1u);
  EXPECT_TRUE(has_warning(m, "2 degenerate")) << warnings_of(m);
}

TEST(ObjImport, ZeroAndNonUnitNormalsAreRepaired) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 6.28\nvn 0 0 0\n"
      "f 1//1 2//1 3//2\n";
  const Model m = import_obj_bundle(make_bundle({{"n.obj", obj}}));
  expect_well_formed(m);
  for (const auto& n : m.mesh.normals) EXPECT_NEAR(glm::length(n - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(ObjImport, SmoothingOffGivesFlatNormalsWhereGroupsAreUsed) {
  // A roof: two faces meeting at a ridge. Smoothed, the ridge vertices get
  // the average; with "s off" on one face, that face stays flat.
  const std::string roof = "v -1 0 0\nv 0 1 0\nv 1 0 0\nv -1 0 -1\nv 0 1 -1\nv 1 0 -1\n";
  const Model smooth = import_obj_bundle(make_bundle({{"r.obj", roof + "s 1\nf 1 2 5 4\nf 2 3 6 5\n"}}));
  EXPECT_EQ(smooth.mesh.positions.size(), 6u);
  const Model mixed = import_obj_bundle(make_bundle({{"r.obj", roof + "s 1\nf 1 2 5 4\ns off\nf 2 3 6 5\n"}}));
  expect_well_formed(mixed);
  EXPECT_EQ(mixed.mesh.positions.size(), 8u);  // the ridge is split
  const glm::vec3 right_face = glm::normalize(glm::vec3(1, 1, 0));
  int flat = 0;
  for (std::size_t v = 0; v < mixed.mesh.positions.size(); ++v) {
    if (glm::length(mixed.mesh.normals[v] - right_face) < 1e-5f) ++flat;
  }
  EXPECT_EQ(flat, 4);
}

TEST(ObjImport, TolerantSyntax) {
  // Empty index slots, a continued face line, CRLF, comments, negative
  // indices, texture coordinates with three components.
  const std::string obj =
      "# comment\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nvt 0 0 0\r\n"
      "f 1// 2// 3//\r\nf 1/1/ \\\r\n 3/1/ 4/1/\r\nf -4 -3 -1\r\n";
  const Model m = import_obj_bundle(make_bundle({{"t.obj", obj}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 3u);
}

TEST(ObjImport, VertexColoursArePerPositionThroughDeduplication) {
  // Two triangles sharing an edge; the shared corners are split by their
  // texture coordinates but keep their position's colour.
  const std::string obj =
      "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0 0.25 0.5 0.75\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
      "f 1/1 2/2 3/3\nf 2/5 4/4 3/5\n";
  const Model m = import_obj_bundle(make_bundle({{"c.obj", obj}}));
  expect_well_formed(m);
  ASSERT_TRUE(m.has_vertex_colors);
  ASSERT_EQ(m.mesh.colors.size(), m.mesh.positions.size());
  EXPECT_EQ(m.mesh.positions.size(), 6u);
  const glm::vec3 expected[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25f, 0.5f, 0.75f}};
  const glm::vec3 corner[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  for (std::size_t v = 0; v < m.mesh.positions.size(); ++v) {
    const glm::vec3 p = glm::vec3(glm::dvec3(m.mesh.positions[v]) + m.mesh.origin);
    bool found = false;
    for (int k = 0; k < 4; ++k) {
      if (glm::length(p - corner[k]) < 1e-6f) {
        EXPECT_EQ(m.mesh.colors[v], expected[k]) << "vertex " << v;
        found = true;
      }
    }
    EXPECT_TRUE(found);
  }
  // With vertex colours and no material, the colours show as painted.
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1.0f));
}

TEST(ObjImport, VertexColoursOnlyWhenEveryVertexHasOne) {
  const Model some = import_obj_bundle(make_bundle({{"c.obj", "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n"}}));
  expect_well_formed(some);
  EXPECT_FALSE(some.has_vertex_colors);
  EXPECT_TRUE(some.mesh.colors.empty());
  // A fourth coordinate (w) is not a colour.
  const Model w = import_obj_bundle(make_bundle({{"w.obj", "v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n"}}));
  EXPECT_FALSE(w.has_vertex_colors);
  // Bytes are read as 0..255, other out-of-range values clamped.
  const Model bytes =
      import_obj_bundle(make_bundle({{"b.obj", "v 0 0 0 255 0 0\nv 1 0 0 0 51 0\nv 0 1 0 0 0 255\nf 1 2 3\n"}}));
  expect_well_formed(bytes);
  ASSERT_TRUE(bytes.has_vertex_colors);
  EXPECT_TRUE(has_warning(bytes, "0..255")) << warnings_of(bytes);
  for (const auto& c : bytes.mesh.colors) EXPECT_NEAR(c.x + c.y + c.z, c.y > 0 ? 0.2f : 1.0f, 1e-6f);
  const Model hdr =
      import_obj_bundle(make_bundle({{"h.obj", "v 0 0 0 1.5 0 0\nv 1 0 0 0 -1 0\nv 0 1 0 0 0 1e999\nf 1 2 3\n"}}));
  expect_well_formed(hdr);
  EXPECT_TRUE(has_warning(hdr, "clamped")) << warnings_of(hdr);
  EXPECT_TRUE(has_warning(hdr, "not a finite number")) << warnings_of(hdr);
}

TEST(ObjImport, SpecularAndShininessFromTheMtl) {
  const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 2 4 3\n";
  const std::string mtl = "newmtl a\nKd 1 1 1\nKs 0.5 0.25 2\nNs 96\nnewmtl b\nKd 1 1 1\nNs 5000\n";
  const Model m = import_obj_bundle(make_bundle({{"m.obj", obj}, {"m.mtl", mtl}}));
  expect_well_formed(m);
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].specular, glm::vec3(0.5f, 0.25f, 1.0f));  // clamped to 0..1
  EXPECT_EQ(m.materials[0].shininess, 96.0f);
  EXPECT_EQ(m.materials[1].specular, glm::vec3(0.0f));
  EXPECT_EQ(m.materials[1].shininess, 1000.0f);  // clamped to the MTL range
}

TEST(ObjImport, NormalMapsAreLinearAndStoredApartFromColourMaps) {
  const std::string obj =
      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
      "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 2/2 4/4 3/3\nusemtl c\nf 1/1 4/4 3/3\n";
  // a: map_Bump (Blender); b: the same file as both colour and normal map,
  // via `bump`; c: `norm` wins over map_Bump.
  const std::string mtl =
      "newmtl a\nKd 1 1 1\nmap_Kd skin.png\nmap_Bump -bm 1 nor.png\n"
      "newmtl b\nKd 1 1 1\nmap_Kd nor.png\nbump nor.png\n"
      "newmtl c\nKd 1 1 1\nmap_Bump height.png\nnorm other.png\n";
  const Model m = import_obj_bundle(make_bundle({{"m.obj", obj},
                                                 {"m.mtl", mtl},
                                                 {"skin.png", tiny_png(200, 100, 50)},
                                                 {"nor.png", tiny_png(128, 128, 255)},
                                                 {"other.png", tiny_png(120, 140, 250)},
                                                 {"height.png", tiny_png(7, 7, 7)}}));
  expect_well_formed(m);
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
  ASSERT_EQ(m.materials.size(), 3u);
  // skin (sRGB), nor (linear), nor (sRGB), other (linear).
  ASSERT_EQ(m.textures.size(), 4u);
  const auto texture = [&](int slot) -> const Texture& { return m.textures.at(static_cast<std::size_t>(slot)); };
  EXPECT_EQ(texture(m.materials[0].diffuse_texture).path, "skin.png");
  EXPECT_EQ(texture(m.materials[0].normal_texture).path, "nor.png");
  EXPECT_EQ(texture(m.materials[0].normal_texture).color_space, ColorSpace::Linear);
  EXPECT_EQ(m.materials[1].normal_texture, m.materials[0].normal_texture);  // decoded once
  EXPECT_EQ(texture(m.materials[1].diffuse_texture).path, "nor.png");
  EXPECT_EQ(texture(m.materials[1].diffuse_texture).color_space, ColorSpace::Srgb);
  EXPECT_NE(m.materials[1].diffuse_texture, m.materials[1].normal_texture);
  EXPECT_EQ(m.materials[2].diffuse_texture, -1);
  EXPECT_EQ(texture(m.materials[2].normal_texture).path, "other.png");
  EXPECT_EQ(texture(m.materials[2].normal_texture).rgba[2], 250);
}

TEST(ObjImport, GreyBumpMapIsAHeightMapAndIgnored) {
  const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
  const std::string mtl = "newmtl a\nKd 1 1 1\nbump height.png\nmap_Kd height.png\n";
  const Model m = import_obj_bundle(make_bundle({{"m.obj", obj}, {"m.mtl", mtl}, {"height.png", tiny_png(9, 9, 9)}}));
  expect_well_formed(m);
  EXPECT_EQ(m.materials[0].normal_texture, -1);
  EXPECT_EQ(m.materials[0].diffuse_texture, 0);  // still fine as a colour map
  EXPECT_EQ(m.textures.size(), 1u);
  EXPECT_TRUE(has_warning(m, "height map")) << warnings_of(m);
}

TEST(ObjImport, MissingNormalMapIsAWarning) {
  const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
  const Model m = import_obj_bundle(make_bundle({{"m.obj", obj}, {"m.mtl", "newmtl a\nmap_Bump gone_NOR.jpg\n"}}));
  expect_well_formed(m);
  EXPECT_EQ(m.materials[0].normal_texture, -1);
  EXPECT_TRUE(has_warning(m, "gone_NOR.jpg")) << warnings_of(m);
  EXPECT_TRUE(has_warning(m, "normal map")) << warnings_of(m);
}

TEST(ObjImport, TangentsFollowTheTextureCoordinates) {
  // A quad in the XY plane facing +Z, U along +X and V along +Y; then the
  // same with U mirrored; then with all UVs equal.
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n";
  const Model plain =
      import_obj_bundle(make_bundle({{"p.obj", quad + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"}}));
  expect_well_formed(plain);
  for (const auto& t : plain.mesh.tangents) {
    EXPECT_NEAR(glm::length(glm::vec3(t) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(t.w, 1.0f);
  }
  const Model mirrored =
      import_obj_bundle(make_bundle({{"m.obj", quad + "vt 1 0\nvt 0 0\nvt 0 1\nvt 1 1\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"}}));
  expect_well_formed(mirrored);
  for (const auto& t : mirrored.mesh.tangents) {
    EXPECT_NEAR(glm::length(glm::vec3(t) - glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(t.w, -1.0f);
  }
  const Model flat = import_obj_bundle(make_bundle({{"f.obj", quad + "vt 0.5 0.5\nf 1/1/1 2/1/1 3/1/1 4/1/1\n"}}));
  expect_well_formed(flat);  // finite, unit, perpendicular to +Z
  for (const auto& t : flat.mesh.tangents) EXPECT_EQ(t.w, 1.0f);
}

TEST(ObjText, PreparationKeepsLineNumbersAndMeaning) {
  EXPECT_EQ(prepare_obj_text("v 1 2 3\nf 1// 2// 3//\n"), "v 1 2 3\nf 1 2 3\n");
  EXPECT_EQ(prepare_obj_text("f 1/1/ 2/2/ \\\n  3/3/\nv 0 0 0"), "f 1/1 2/2 3/3\n\nv 0 0 0\n");
  EXPECT_EQ(prepare_obj_text("usemtl  a b\tc  \n"),
            "usemtl a\x1f"
            "b\x1f"
            "c\n");
  EXPECT_EQ(prepare_obj_text("usemtl plain\nf 1/2/3 4//5\n"), "usemtl plain\nf 1/2/3 4//5\n");
  // An mtllib line reaches the material reader in one piece.
  EXPECT_EQ(prepare_obj_text("mtllib  mats\\a.mtl my\\ file.mtl \n"), "mtllib mats\\\\a.mtl\\ my\\\\\\ file.mtl\n");
  EXPECT_EQ(prepare_obj_text("mtllib plain.mtl\n"), "mtllib plain.mtl\n");
  EXPECT_EQ(material_alias(" a  b "),
            "a\x1f"
            "b");
}

// Faces naming a position the file does not define are found before
// tinyobj reads the text (it drops such quads without a word): a positive
// index past the file's last position, a negative one reaching back past
// the first, or 0. A positive index may name a position defined further
// down.
TEST(ObjText, FindsFacesNamingMissingPositions) {
  auto missing_line = [](std::string_view text) {
    ObjTextFindings findings;
    prepare_obj_text(text, &findings);
    return findings.missing_vertex_line;
  };
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
  EXPECT_EQ(missing_line(verts + "f 1 2 3 4\nf -1 -2 -3\n"), 0u);
  EXPECT_EQ(missing_line("f 1 2 3\n" + verts), 0u) << "a position defined further down";
  EXPECT_EQ(missing_line(verts + "f 1 2 3\nf 1/1 2/2 3/3 9/4\n"), 6u);
  EXPECT_EQ(missing_line(verts + "f -1 -2 -5\n"), 5u);
  EXPECT_EQ(missing_line("v 0 0 0\nf -1 -2 -3\nv 1 0 0\nv 0 1 0\n"), 2u) << "counted back from line 2";
  EXPECT_EQ(missing_line(verts + "f 0 1 2\n"), 5u);
  EXPECT_EQ(missing_line(verts + "f 1 2 99999999999999999999999\n"), 5u);
  EXPECT_EQ(missing_line(verts + "f 1 2 -9223372036854775808\n"), 5u);
  EXPECT_EQ(missing_line(verts + "f 1 2 \\\n 9\n"), 5u) << "a continued face is named by its first line";
}

TEST(TextureDecode, DecodesPng) {
  const Texture t = decode_texture(tiny_png(10, 20, 30, 3, 5), "x.png");
  EXPECT_EQ(t.path, "x.png");
  EXPECT_EQ(t.width, 3);
  EXPECT_EQ(t.height, 5);
  ASSERT_EQ(t.rgba.size(), 3u * 5u * 4u);
  EXPECT_EQ(t.rgba[0], 10);
  EXPECT_EQ(t.rgba[1], 20);
  EXPECT_EQ(t.rgba[2], 30);
  EXPECT_EQ(t.rgba[3], 255);
}

TEST(TextureDecode, RefusesGarbageAndOversizedImages) {
  EXPECT_THROW(decode_texture("", "e.png"), std::runtime_error);
  EXPECT_THROW(decode_texture("GIF89a but not really", "g.gif"), std::runtime_error);
  const std::string png = tiny_png(0, 0, 0, 64, 16);
  EXPECT_THROW(decode_texture(png, "big.png", {32, 1u << 20}), std::runtime_error);
  EXPECT_THROW(decode_texture(png, "big.png", {8192, 512}), std::runtime_error);
  EXPECT_NO_THROW(decode_texture(png, "ok.png", {64, 1024}));
  // A truncated file is refused, not read past its end.
  EXPECT_THROW(decode_texture(png.substr(0, png.size() / 2), "cut.png"), std::runtime_error);
}

// ---- real models from ../shared/models (never copied into the repo) ----

TEST(ObjImportShared, Spot) {
  TOOND_REQUIRE_SHARED_MODELS();
  const Model m = import_obj_bundle(bundle_from_folder(test::shared_models_dir() / "spot"));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 5856u);
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].width, 1024);
  EXPECT_EQ(m.textures[0].height, 1024);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].diffuse_texture, 0);
  EXPECT_EQ(m.materials[0].normal_texture, -1);
  // nvdiffrec's "Ks 0 0.25 0" (roughness, metalness) is kept as written.
  EXPECT_NEAR(m.materials[0].specular.y, 0.25f, 1e-6f);
  EXPECT_EQ(m.materials[0].specular.x, 0.0f);
  EXPECT_EQ(m.materials[0].shininess, 32.0f);  // no Ns
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
}

TEST(ObjImportShared, WindmillHasTwoTexturedMaterials) {
  TOOND_REQUIRE_SHARED_MODELS();
  const Model m = import_obj_bundle(bundle_from_folder(test::shared_models_dir() / "windmill"));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 2722u);
  ASSERT_EQ(m.materials.size(), 2u);
  // The two map_Kd colour maps and the two map_Bump normal maps; map_Ns
  // (specular) is not read.
  EXPECT_EQ(m.textures.size(), 4u);
  EXPECT_EQ(m.mesh.submeshes.size(), 2u);
  for (const auto& mat : m.materials) {
    ASSERT_GE(mat.diffuse_texture, 0) << mat.name;
    ASSERT_GE(mat.normal_texture, 0) << mat.name;
    const Texture& colour = m.textures[static_cast<std::size_t>(mat.diffuse_texture)];
    const Texture& normal = m.textures[static_cast<std::size_t>(mat.normal_texture)];
    EXPECT_EQ(colour.color_space, ColorSpace::Srgb) << mat.name;
    EXPECT_EQ(normal.color_space, ColorSpace::Linear) << mat.name;
    EXPECT_NE(colour.path.find("_COL"), std::string::npos) << colour.path;
    EXPECT_NE(normal.path.find("_NOR"), std::string::npos) << normal.path;
    EXPECT_EQ(mat.specular, glm::vec3(0.0f));  // Ks 0 0 0
    EXPECT_EQ(mat.shininess, 0.0f);            // Ns 0 (Blender: fully rough)
  }
  EXPECT_NE(m.materials[0].diffuse_texture, m.materials[1].diffuse_texture);
  EXPECT_NE(m.materials[0].normal_texture, m.materials[1].normal_texture);
  EXPECT_FALSE(m.has_vertex_colors);
  // UV-mapped: most vertices get a tangent from their UVs, and the tangent
  // frame is orthonormal everywhere (expect_well_formed).
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
}

TEST(ObjImportShared, DogTextureInSubfolderResolves) {
  TOOND_REQUIRE_SHARED_MODELS();
  const Model m = import_obj_bundle(bundle_from_folder(test::shared_models_dir() / "kenney-cube-pet-dog"));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 490u);
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].path, "Textures/colormap.png");
  EXPECT_EQ(m.textures[0].width, 512);
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
  // Blocky, hard-edged: shading normals are split but outline normals are
  // shared per position.
  for (std::size_t v = 0; v < m.mesh.positions.size(); ++v) {
    for (std::size_t w = v + 1; w < m.mesh.positions.size(); ++w) {
      if (m.mesh.positions[w] == m.mesh.positions[v]) {
        ASSERT_EQ(m.mesh.outline_normals[w], m.mesh.outline_normals[v]);
      }
    }
  }
}

TEST(ObjImportShared, TeapotWithoutNormals) {
  TOOND_REQUIRE_SHARED_MODELS();
  const Model m = import_obj_bundle(bundle_from_folder(test::shared_models_dir() / "utah-teapot"));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 6320u);
}

// Every parser edge case either imports into a well-formed model or is an
// ImportError; only the files with no faces at all are refused.
TEST(ObjImportShared, EdgeCasesNeverBreakTheImporter) {
  TOOND_REQUIRE_SHARED_MODELS();
  const auto root = test::shared_models_dir() / "edge-cases";
  const std::set<std::string> expected_refusals = {"tinyobjloader/line-prim.obj", "tinyobjloader/points-prim.obj"};
  int imported = 0;
  for (const char* folder : {"tinyobjloader", "assimp", "trimesh"}) {
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      std::string ext = entry.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (ext != ".obj") continue;
      const std::string name = entry.path().filename().string();
      const std::string key = std::string(folder) + "/" + name;
      SCOPED_TRACE(key);
      const Bundle bundle = bundle_from_folder(root / folder, name);
      try {
        const Model m = import_obj_bundle(bundle);
        expect_well_formed(m);
        EXPECT_FALSE(expected_refusals.count(key));
        ++imported;
      } catch (const ImportError& e) {
        EXPECT_TRUE(expected_refusals.count(key)) << e.what();
        EXPECT_EQ(e.file(), name);
      }
    }
  }
  EXPECT_GT(imported, 60);
}

TEST(ObjImportShared, FuzeTextureWithSpaceInName) {
  TOOND_REQUIRE_SHARED_MODELS();
  const Model m = import_obj_bundle(bundle_from_folder(test::shared_models_dir() / "edge-cases/trimesh", "fuze.obj"));
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].path, "fuze uv.jpg");
}

}  // namespace
}  // namespace toond::scene
