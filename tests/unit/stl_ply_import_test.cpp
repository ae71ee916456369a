// STL and PLY, read by toond's own readers: every form gives the same mesh,
// files without normals are shaded by angle, and hostile files are an
// ImportError naming the file, not a crash or a huge allocation.
#include <gtest/gtest.h>

#include <string>

#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/reading/import_error.h"
#include "scene/reading/import_limits.h"
#include "support/mesh_file_writers.h"

namespace toond::scene {
namespace {

using test::PlyForm;
using test_checks::expect_well_formed;
using test_checks::make_bundle;
using test_checks::warnings_of;

Model import_one(const std::string& name, const std::string& bytes, const ImportLimits& limits = {},
                 const ImportChoices& choices = {}) {
  return import_bundle(make_bundle({{name, bytes}}), limits, choices);
}

std::string import_error(const std::string& name, const std::string& bytes, const ImportLimits& limits = {}) {
  try {
    import_one(name, bytes, limits);
  } catch (const ImportError& e) {
    EXPECT_EQ(e.file(), name);
    return e.what();
  }
  ADD_FAILURE() << name << " was read";
  return {};
}

void expect_flat_cube(const Model& m) {
  expect_well_formed(m);
  EXPECT_EQ(m.mesh.triangle_count(), 12u);
  // Each face its own four corners: normals by angle split the 90° edges.
  EXPECT_EQ(m.mesh.positions.size(), 24u);
  for (std::size_t t = 0; t < m.mesh.indices.size(); t += 3) {
    const glm::dvec3 face = triangle_normal(glm::dvec3(m.mesh.positions[m.mesh.indices[t]]),
                                            glm::dvec3(m.mesh.positions[m.mesh.indices[t + 1]]),
                                            glm::dvec3(m.mesh.positions[m.mesh.indices[t + 2]]));
    EXPECT_NEAR(glm::dot(glm::dvec3(m.mesh.normals[m.mesh.indices[t]]), face), 1.0, 1e-6);
  }
}

TEST(StlImport, BinaryAndAsciiGiveTheSameFlatCube) {
  const Model binary = import_one("cube.stl", test::binary_stl(test::cube_triangles()));
  const Model ascii = import_one("cube.stl", test::ascii_stl(test::cube_triangles()));
  expect_flat_cube(binary);
  expect_flat_cube(ascii);
  EXPECT_EQ(binary.mesh.positions, ascii.mesh.positions);
  EXPECT_EQ(binary.mesh.indices, ascii.mesh.indices);
  EXPECT_TRUE(binary.warnings.empty()) << warnings_of(binary);
}

TEST(StlImport, ABinaryFileWhoseHeaderSaysSolidIsReadAsBinary) {
  const Model m = import_one("cube.stl", test::binary_stl(test::cube_triangles(), "solid cube exported by a CAD tool"));
  expect_flat_cube(m);
}

TEST(StlImport, CountsThatLieAndCutFilesAreRefused) {
  std::string lie = test::binary_stl({});
  lie[80] = lie[81] = lie[82] = lie[83] = '\xff';  // 2^32 - 1 triangles in 84 bytes
  EXPECT_NE(import_error("lie.stl", lie).find("cut short, or the count is wrong"), std::string::npos);
  // The same with a header that starts like ASCII: still a binary file.
  std::string solid_lie = test::binary_stl({}, "solid but binary");
  solid_lie[80] = solid_lie[81] = solid_lie[82] = solid_lie[83] = '\xff';
  EXPECT_NE(import_error("lie.stl", solid_lie).find("cut short, or the count is wrong"), std::string::npos);
  std::string cut = test::binary_stl(test::cube_triangles());
  cut.resize(cut.size() - 7);
  EXPECT_NE(import_error("cut.stl", cut).find("cut short"), std::string::npos);
  EXPECT_NE(import_error("tiny.stl", "abc").find("too few"), std::string::npos);
}

TEST(StlImport, BadAsciiIsRefusedWithItsLine) {
  EXPECT_NE(import_error("a.stl", "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 zero 0\n").find("line 4"),
            std::string::npos);
  EXPECT_NE(import_error("a.stl", "solid x\nvertex 0 0 0\n").find("outside"), std::string::npos);
  EXPECT_NE(import_error("a.stl", "solid x\nouter loop\nvertex 0 0 0\n").find("ends inside a loop"), std::string::npos);
  EXPECT_NE(import_error("a.stl",
                         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                         "vertex nan 1 0\nendloop\nendfacet\n")
                .find("not a finite number"),
            std::string::npos);
}

TEST(StlImport, MoreTrianglesThanTheLimitIsRefusedBeforeReading) {
  ImportLimits limits;
  limits.max_triangles = 5;
  try {
    import_one("cube.stl", test::binary_stl(test::cube_triangles()), limits);
    FAIL() << "read";
  } catch (const ImportLimitError& e) {
    EXPECT_EQ(e.limit(), ImportLimit::Triangles);
  }
}

TEST(PlyImport, AsciiAndBothByteOrdersGiveTheSameFlatCube) {
  const Model ascii = import_one("cube.ply", test::ply(test::cube_triangles(), PlyForm::Ascii));
  const Model little = import_one("cube.ply", test::ply(test::cube_triangles(), PlyForm::BinaryLittle));
  const Model big = import_one("cube.ply", test::ply(test::cube_triangles(), PlyForm::BinaryBig));
  expect_flat_cube(ascii);
  EXPECT_EQ(ascii.mesh.positions, little.mesh.positions);
  EXPECT_EQ(ascii.mesh.positions, big.mesh.positions);
  EXPECT_EQ(ascii.mesh.indices, big.mesh.indices);
}

TEST(PlyImport, NormalsUvsColoursAndPolygonsAreRead) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float quality\nelement face 1\n"
      "property list uchar int vertex_indices\nproperty list uchar float texcoord\nelement edge 1\n"
      "property int vertex1\nproperty int vertex2\nend_header\n"
      "0 0 0 0 0 1 0 0 255 0 0 0.5\n1 0 0 0 0 1 1 0 0 255 0 0.5\n1 1 0 0 0 1 1 1 0 0 255 0.5\n"
      "0 1 0 0 0 1 0 1 255 255 255 0.5\n"
      "4 0 1 2 3 8 0 0 1 0 1 1 0 1\n0 1\n";
  // Read in the file's own axes (PLY is Z-up by default): what was written.
  ImportChoices as_written;
  as_written.up = ImportChoices::Up::Y;
  const Model m = import_one("quad.ply", ply, {}, as_written);
  EXPECT_EQ(m.mesh.triangle_count(), 2u);
  EXPECT_TRUE(m.has_vertex_colors);
  for (std::size_t v = 0; v < m.mesh.positions.size(); ++v) {
    EXPECT_EQ(m.mesh.normals[v], glm::vec3(0, 0, 1));
    // Colours 0..1, texture coordinates as written.
    const glm::vec3 p = m.mesh.positions[v] + glm::vec3(m.mesh.origin);
    EXPECT_EQ(m.mesh.texcoords[v], glm::vec2(p.x, p.y));
    if (p.x == 0 && p.y == 0) {
      EXPECT_EQ(m.mesh.colors[v], glm::vec3(1, 0, 0));
    }
  }
  EXPECT_NE(warnings_of(m).find("element \"edge\" is not read"), std::string::npos) << warnings_of(m);
  // By default a PLY is Z-up, its tools' convention: the quad's +Z normal
  // becomes toond's +Y.
  const Model upright = import_one("quad.ply", ply);
  for (const glm::vec3& n : upright.mesh.normals) EXPECT_FLOAT_EQ(n.y, 1.0f);
  EXPECT_NE(warnings_of(m).find("vertex properties not read: quality"), std::string::npos) << warnings_of(m);
  EXPECT_NE(warnings_of(m).find("face properties not read: texcoord"), std::string::npos) << warnings_of(m);
}

TEST(PlyImport, HostileHeadersAndCountsAreRefused) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n";
  EXPECT_NE(import_error("h.ply", "ply\nformat ascii 1.0\n" + std::string(70000, '#')).find("end_header"),
            std::string::npos);
  EXPECT_NE(import_error("h.ply", "ply\ncomment " + std::string(70000, 'x') + "\nend_header\n").find("64 KiB"),
            std::string::npos);
  EXPECT_NE(import_error("h.ply",
                         "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\n"
                         "property float y\nproperty float z\nend_header\n0 0 0\n")
                .find("claims"),
            std::string::npos);
  EXPECT_NE(import_error("h.ply", head + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n").find("names vertex 7"),
            std::string::npos);
  EXPECT_NE(import_error("h.ply", head + "end_header\n0 0 0\n1 0 0\n").find("data ends"), std::string::npos);
  EXPECT_NE(import_error("h.ply", "ply\nformat unknown 1.0\nend_header\n").find("unknown format"), std::string::npos);
  EXPECT_NE(import_error("h.ply", "plx\nend_header\n").find("does not start"), std::string::npos);
  EXPECT_NE(import_error("h.ply", head + "end_header\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n").find("not a finite number"),
            std::string::npos);
  std::string cut = test::ply(test::cube_triangles(), PlyForm::BinaryLittle);
  cut.resize(cut.size() - 5);
  EXPECT_NE(import_error("cut.ply", cut).find("data ends"), std::string::npos);
}

}  // namespace
}  // namespace toond::scene
