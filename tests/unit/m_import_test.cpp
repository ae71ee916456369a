#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "scene/import/m_import.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/reading/import_error.h"
#include "scene/store/model_store.h"

namespace toond::scene {
namespace {

using test_checks::expect_import_error;
using test_checks::expect_well_formed;
using test_checks::has_warning;
using test_checks::make_bundle;
using test_checks::warnings_of;

// Vertex ids out of order and with gaps; outward (counter-clockwise) faces.
const std::string kTetrahedron =
    "# a tetrahedron\n"
    "Vertex 10  0 0 0\n"
    "Vertex 20  1 0 0\n"
    "Vertex 5   0 1 0\n"
    "Vertex 7   0 0 1\n"
    "Face 1  10 5 20\n"
    "Face 2  10 20 7\n"
    "Face 3  20 5 7\n"
    "Face 4  5 10 7\n";

glm::vec3 corner(int bits) { return {(bits & 1) ? 1.0f : -1.0f, (bits & 2) ? 1.0f : -1.0f, (bits & 4) ? 1.0f : -1.0f}; }

std::string number(float v) { return std::to_string(v); }

// A cube of quads with per-vertex normal, uv and rgb, vertex ids 100 + 3i
// listed backwards and after the faces, plus Edge and Corner lines.
std::string cube_m(const std::string& eol = "\n") {
  const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  std::string text = "# cube" + eol;
  for (int f = 0; f < 6; ++f) {
    text += "Face " + std::to_string(f + 1);
    for (const int c : faces[f]) text += " " + std::to_string(100 + 3 * c);
    text += " {mat=1}" + eol;
  }
  text += "Edge 100 103 {sharp}" + eol;
  for (int i = 7; i >= 0; --i) {
    const glm::vec3 p = corner(i);
    const glm::vec3 n = glm::normalize(p) * 2.0f;  // not unit: normalised on import
    text += "Vertex " + std::to_string(100 + 3 * i) + " " + number(p.x) + " " + number(p.y) + " " + number(p.z) +
            " {wid=" + std::to_string(i) + " normal=(" + number(n.x) + " " + number(n.y) + " " + number(n.z) +
            ") uv=(" + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + ") rgb=(" + std::to_string(i & 1) +
            " 0.5 " + std::to_string((i >> 2) & 1) + ")}" + eol;
  }
  text += "Corner 100 1 {normal=(0 0 1)}" + eol;
  return text;
}

Model import_any(const Bundle& bundle) { return import_bundle(bundle); }

// Its faces meet at 70.5°, sharper than the default 30°: flat faces.
TEST(MImport, TetrahedronWithoutNormalsGetsFlatOutwardNormals) {
  const Model m = import_m_bundle(make_bundle({{"tet.m", kTetrahedron}}));
  expect_well_formed(m);
  EXPECT_TRUE(m.warnings.empty()) << warnings_of(m);
  EXPECT_EQ(m.mesh.triangle_count(), 4u);
  EXPECT_EQ(m.mesh.positions.size(), 12u);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].name, "default");
  EXPECT_EQ(m.materials[0].diffuse, glm::vec3(0.8f));
  EXPECT_FALSE(m.has_vertex_colors);
  EXPECT_EQ(m.mesh.origin, glm::dvec3(0.5));
  const glm::vec3 centroid = glm::vec3(glm::dvec3(0.25) - m.mesh.origin);
  for (std::size_t v = 0; v < m.mesh.positions.size(); ++v) {
    EXPECT_GT(glm::dot(m.mesh.normals[v], m.mesh.positions[v] - centroid), 0.0f) << v;
    EXPECT_EQ(m.mesh.texcoords[v], glm::vec2(0.0f));
  }
  for (std::size_t t = 0; t < m.mesh.indices.size(); t += 3) {
    const glm::dvec3 a = m.mesh.positions[m.mesh.indices[t]];
    const glm::dvec3 b = m.mesh.positions[m.mesh.indices[t + 1]];
    const glm::dvec3 c = m.mesh.positions[m.mesh.indices[t + 2]];
    const glm::dvec3 face = triangle_normal(a, b, c);
    EXPECT_GT(glm::dot(face, (a + b + c) / 3.0 - glm::dvec3(centroid)), 0.0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(glm::dot(glm::dvec3(m.mesh.normals[m.mesh.indices[t + k]]), face), 1.0, 1e-6);
    }
  }
}

TEST(MImport, CubeWithQuadsNormalsUVsAndColours) {
  for (const std::string eol : {"\n", "\r\n"}) {
    SCOPED_TRACE(eol == "\n" ? "LF" : "CRLF");
    const Model m = import_m_bundle(make_bundle({{"cube.m", cube_m(eol)}}));
    expect_well_formed(m);
    EXPECT_EQ(m.mesh.triangle_count(), 12u);
    EXPECT_EQ(m.mesh.positions.size(), 8u);
    ASSERT_TRUE(m.has_vertex_colors);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].diffuse, glm::vec3(1.0f));  // the colours show as painted
    // One warning for all the lines it does not read.
    ASSERT_EQ(m.warnings.size(), 1u) << warnings_of(m);
    EXPECT_TRUE(has_warning(m, "Edge (1)")) << warnings_of(m);
    EXPECT_TRUE(has_warning(m, "Corner (1)")) << warnings_of(m);
    EXPECT_TRUE(has_warning(m, "line 8")) << warnings_of(m);  // the first of them
    for (std::size_t v = 0; v < 8; ++v) {
      const glm::vec3 p = m.mesh.positions[v];
      EXPECT_NEAR(glm::length(m.mesh.normals[v] - glm::normalize(p)), 0.0f, 1e-5f);
      const int bits = (p.x > 0 ? 1 : 0) | (p.y > 0 ? 2 : 0) | (p.z > 0 ? 4 : 0);
      EXPECT_EQ(m.mesh.texcoords[v], glm::vec2(static_cast<float>(bits & 1), static_cast<float>((bits >> 1) & 1)));
      EXPECT_EQ(m.mesh.colors[v], glm::vec3(static_cast<float>(bits & 1), 0.5f, static_cast<float>((bits >> 2) & 1)));
    }
    for (std::size_t t = 0; t < m.mesh.indices.size(); t += 3) {
      const glm::dvec3 a = m.mesh.positions[m.mesh.indices[t]];
      const glm::dvec3 b = m.mesh.positions[m.mesh.indices[t + 1]];
      const glm::dvec3 c = m.mesh.positions[m.mesh.indices[t + 2]];
      EXPECT_GT(glm::dot(triangle_normal(a, b, c), (a + b + c) / 3.0), 0.0);
    }
  }
}

TEST(MImport, QuadWithUVsGetsTangentsAlongU) {
  const std::string quad =
      "Vertex 1 0 0 0 {uv=(0 0)}\nVertex 2 1 0 0 {uv=(1 0)}\nVertex 3 1 1 0 {uv=(1 1)}\n"
      "Vertex 4 0 1 0 {uv=(0 1)}\nFace 1 1 2 3 4\n";
  const Model m = import_m_bundle(make_bundle({{"q.m", quad}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 2u);
  for (std::size_t v = 0; v < m.mesh.positions.size(); ++v) {
    EXPECT_NEAR(glm::length(m.mesh.normals[v] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(m.mesh.tangents[v]) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(m.mesh.tangents[v].w, 1.0f);
  }
}

TEST(MImport, PentagonIsFanTriangulated) {
  const std::string text =
      "Vertex 1 1 0 0\nVertex 2 0.309 0.951 0\nVertex 3 -0.809 0.588 0\nVertex 4 -0.809 -0.588 0\n"
      "Vertex 5 0.309 -0.951 0\nFace 9 1 2 3 4 5\n";
  const Model m = import_m_bundle(make_bundle({{"p.m", text}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 3u);
  for (const auto& n : m.mesh.normals) EXPECT_NEAR(glm::length(n - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(MImport, BadFaceIndexIsAnImportErrorNamingTheLine) {
  const std::string text = "# tri\nVertex 1 0 0 0\nVertex 2 1 0 0\nVertex 3 0 1 0\nFace 1 1 2 3\nFace 2 1 3 99\n";
  expect_import_error(import_any, make_bundle({{"bad.m", text}}), "bad.m", "bad.m: line 6", "vertex 99");
  try {
    import_m_bundle(make_bundle({{"bad.m", text}}));
    ADD_FAILURE() << "no ImportError";
  } catch (const ImportError& e) {
    EXPECT_EQ(e.file(), "bad.m");
  }
}

TEST(MImport, MalformedLinesAreImportErrorsNamingTheLine) {
  const std::string verts = "Vertex 1 0 0 0\nVertex 2 1 0 0\nVertex 3 0 1 0\n";
  expect_import_error(import_any, make_bundle({{"a.m", verts + "Vertex 2 5 5 5\nFace 1 1 2 3\n"}}), "a.m", "line 4",
                      "first on line 2");
  expect_import_error(import_any, make_bundle({{"a.m", "Vertex 1 0 0\n" + verts}}), "a.m", "line 1", "Vertex id x y z");
  expect_import_error(import_any, make_bundle({{"a.m", verts + "Vertex x 0 0 0\n"}}), "a.m", "line 4");
  expect_import_error(import_any, make_bundle({{"a.m", verts + "Vertex 4 0 zero 0\n"}}), "a.m", "line 4");
  expect_import_error(import_any, make_bundle({{"a.m", verts + "Face 1 1 2\n"}}), "a.m", "line 4", "at least three");
  expect_import_error(import_any, make_bundle({{"a.m", verts + "Face 1 1 2 3.5\n"}}), "a.m", "line 4");
  expect_import_error(import_any, make_bundle({{"a.m", verts + "Vertex 4 1e999 0 0\nFace 1 1 2 3\n"}}), "a.m",
                      "vertex 4 (line 4)", "not a finite number");
}

TEST(MImport, NothingToRenderIsAnImportError) {
  expect_import_error(import_any, make_bundle({{"e.m", ""}}), "e.m", "no faces");
  expect_import_error(import_any, make_bundle({{"e.m", "# only comments\nVertex 1 0 0 0\n"}}), "e.m", "no faces");
  expect_import_error(import_any,
                      make_bundle({{"e.m", "Vertex 1 0 0 0\nVertex 2 1 0 0\nVertex 3 2 0 0\nFace 1 1 2 3\n"}}), "e.m",
                      "no faces");
}

TEST(MImport, TolerantAttributes) {
  // A zero normal is recomputed, a malformed attribute warned about,
  // unknown attributes and face attributes ignored, partial colours
  // dropped, numbers with '+' and exponents read.
  const std::string text =
      "Vertex 1 +0 0 0e0 {normal=(0 0 0) rgb=(1 0 0)}\n"
      "Vertex 2 1 0 0 {normal=(0 0 1 2) flag}\n"
      "Vertex 3 0 1E0 0{sharp=1 uv=(0.5 0.5)}\n"
      "Face 1 1 2 3 {rgb=(1 1 1)}\n";
  const Model m = import_m_bundle(make_bundle({{"t.m", text}}));
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 1u);
  for (const auto& n : m.mesh.normals) EXPECT_NEAR(glm::length(n - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_FALSE(m.has_vertex_colors);
  EXPECT_TRUE(has_warning(m, "1 vertex attribute was malformed")) << warnings_of(m);
  EXPECT_TRUE(has_warning(m, "only 1 of 3 vertices have rgb")) << warnings_of(m);
}

TEST(MImport, FarFromOriginIsRecentredInDouble) {
  const std::string text =
      "Vertex 1 1000000 0 -2000000\nVertex 2 1000001.001 0 -2000000\nVertex 3 1000000 1 -2000000\nFace 1 1 2 3\n";
  const Model m = import_m_bundle(make_bundle({{"far.m", text}}));
  expect_well_formed(m);
  EXPECT_NEAR(m.mesh.origin.x, 1e6 + 0.5005, 1e-9);
  EXPECT_NEAR(m.mesh.bounds.max.x - m.mesh.bounds.min.x, 1.001f, 1e-6f);
}

TEST(BundleImport, PicksTheImporterByExtension) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_EQ(import_bundle(make_bundle({{"tet.m", kTetrahedron}})).mesh.triangle_count(), 4u);
  EXPECT_EQ(import_bundle(make_bundle({{"sub/TET.M", kTetrahedron}, {"notes.txt", "x"}})).mesh.triangle_count(), 4u);
  EXPECT_EQ(import_bundle(make_bundle({{"tri.obj", obj}, {"tri.mtl", ""}})).mesh.triangle_count(), 1u);
  EXPECT_EQ(import_bundle(make_bundle({{"Tri.OBJ", obj}})).mesh.triangle_count(), 1u);
  // Names that only contain the extensions are not model files.
  expect_import_error(import_any, make_bundle({{"a.mtl", "newmtl a\n"}, {"b.obj.txt", obj}, {"c.mm", ""}}), "",
                      "no model (.obj, .gltf, .glb, .stl, .ply, .iqm, .fbx", "'a.mtl'");
  expect_import_error(import_any, Bundle{}, "", "no model (.obj, .gltf, .glb, .stl, .ply, .iqm, .fbx", "empty");
}

TEST(BundleImport, ExactlyOneModelFile) {
  try {
    import_bundle(make_bundle({{"a.obj", "v 0 0 0\n"}, {"b.m", kTetrahedron}}));
    ADD_FAILURE() << "no ImportError";
  } catch (const ImportError& e) {
    EXPECT_EQ(e.file(), "b.m");
    EXPECT_NE(std::string(e.what()).find("'a.obj'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'b.m'"), std::string::npos) << e.what();
  }
  expect_import_error(import_any, make_bundle({{"a.m", kTetrahedron}, {"x/b.M", kTetrahedron}}), "x/b.M", "'a.m'",
                      "'x/b.M'");
  // The format importers keep their own entry points.
  EXPECT_THROW(import_m_bundle(make_bundle({{"a.obj", "v 0 0 0\n"}})), ImportError);
  EXPECT_EQ(import_obj_bundle(make_bundle({{"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}, {"b.m", ""}}))
                .mesh.triangle_count(),
            1u);
}

TEST(BundleImport, ModelStoreTakesMFiles) {
  const auto dir = std::filesystem::temp_directory_path() / ("toond-store-m-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  {
    ModelStore store(dir);
    const auto result = store.put(make_bundle({{"tet.m", kTetrahedron}}));
    EXPECT_TRUE(result.created);
    EXPECT_EQ(result.info.triangles, 4u);
    EXPECT_EQ(result.info.materials, 1u);
    EXPECT_THROW(store.put(make_bundle({{"bad.m", "Face 1 1 2 3\n"}})), ImportError);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace toond::scene
