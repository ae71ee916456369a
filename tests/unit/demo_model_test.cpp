#include <gtest/gtest.h>

#include <cmath>

#include "image/png_codec.h"
#include "scene/import/demo_model.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/store/model_store.h"

namespace toond::scene {
namespace {

TEST(DemoModel, IsDeterministic) {
  const Bundle a = make_demo_bundle();
  const Bundle b = make_demo_bundle();
  EXPECT_EQ(a.files(), b.files());
  EXPECT_EQ(bundle_id(a), bundle_id(b));
  ASSERT_NE(a.find("demo.obj"), nullptr);
  ASSERT_NE(a.find("demo.mtl"), nullptr);
  ASSERT_NE(a.find("textures/demo.png"), nullptr);
  ASSERT_NE(a.find("ramps/sharp.png"), nullptr);
  ASSERT_NE(a.find("textures/floor.png"), nullptr);
  EXPECT_EQ(a.files().size(), 5u);
}

TEST(DemoModel, ImportsCleanly) {
  const Model m = import_obj_bundle(make_demo_bundle());
  for (const auto& w : m.warnings) ADD_FAILURE() << "warning: " << w;
  // Sphere: 2 caps of 48 triangles and 22 bands of 48 quads; box: 6 quads.
  EXPECT_EQ(m.mesh.triangle_count(), 2u * 48u + 22u * 48u * 2u + 12u);
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_EQ(m.materials[0].name, "body");
  EXPECT_EQ(m.materials[0].diffuse_texture, 0);
  EXPECT_EQ(m.materials[1].name, "base");
  EXPECT_EQ(m.materials[1].diffuse_texture, -1);
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].path, "textures/demo.png");
  EXPECT_EQ(m.textures[0].width, 256);
  EXPECT_EQ(m.textures[0].height, 128);
  ASSERT_EQ(m.mesh.submeshes.size(), 2u);
  EXPECT_EQ(m.mesh.submeshes[1].index_count, 36u);

  // Y is up, unit-ish scale: the box spans 1.6 wide, the whole 1.55 high.
  const glm::vec3 size = m.mesh.bounds.max - m.mesh.bounds.min;
  EXPECT_NEAR(size.x, 1.6f, 1e-5f);
  EXPECT_NEAR(size.y, 1.55f, 1e-5f);
  EXPECT_NEAR(size.z, 1.6f, 1e-5f);
  EXPECT_NEAR(m.mesh.origin.y, 0.775, 1e-9);
}

TEST(DemoModel, NormalsAreOutwardAndWindingAgrees) {
  const Model m = import_obj_bundle(make_demo_bundle());
  const Mesh& mesh = m.mesh;
  const glm::vec3 sphere_centre = glm::vec3(glm::dvec3(0.0, 0.95, 0.0) - mesh.origin);
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = mesh.positions[mesh.indices[t]];
    const glm::dvec3 b = mesh.positions[mesh.indices[t + 1]];
    const glm::dvec3 c = mesh.positions[mesh.indices[t + 2]];
    const glm::vec3 face(triangle_normal(a, b, c));
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(glm::dot(face, mesh.normals[mesh.indices[t + static_cast<std::size_t>(k)]]), 0.5f)
          << "triangle " << t / 3;
    }
  }
  const auto& sub_sphere = mesh.submeshes[0];
  for (std::uint32_t i = sub_sphere.first_index; i < sub_sphere.first_index + sub_sphere.index_count; ++i) {
    const std::uint32_t v = mesh.indices[i];
    const glm::vec3 radial = glm::normalize(mesh.positions[v] - sphere_centre);
    ASSERT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(mesh.normals[v], radial), 0.9999f);
  }
  // The box is hard-edged: 24 vertices with axis-aligned normals, and the
  // three copies of each corner share one outline normal.
  const auto& sub_box = mesh.submeshes[1];
  std::vector<std::uint32_t> box;
  for (std::uint32_t i = sub_box.first_index; i < sub_box.first_index + sub_box.index_count; ++i) {
    if (std::find(box.begin(), box.end(), mesh.indices[i]) == box.end()) box.push_back(mesh.indices[i]);
  }
  EXPECT_EQ(box.size(), 24u);
  for (const auto v : box) {
    const glm::vec3 n = mesh.normals[v];
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);
    for (const auto w : box) {
      if (mesh.positions[w] == mesh.positions[v]) {
        EXPECT_EQ(mesh.outline_normals[w], mesh.outline_normals[v]);
      }
    }
    const glm::vec3 o = mesh.outline_normals[v];
    EXPECT_GT(std::abs(o.x), 0.3f);
    EXPECT_GT(std::abs(o.y), 0.3f);
    EXPECT_GT(std::abs(o.z), 0.3f);
  }
}

TEST(DemoModel, TextureIsAColourfulPattern) {
  const Bundle bundle = make_demo_bundle();
  const image::Image img = image::decode_png(*bundle.find("textures/demo.png"));
  ASSERT_EQ(img.width, 256);
  ASSERT_EQ(img.height, 128);
  const std::uint8_t* a = img.pixel(5, 5);
  const std::uint8_t* b = img.pixel(40, 5);
  EXPECT_NE(std::vector<std::uint8_t>(a, a + 3), std::vector<std::uint8_t>(b, b + 3));
  EXPECT_NE(a[0], a[2]);  // not grey
}

}  // namespace
}  // namespace toond::scene
