// The .glb toon writes from an OBJ bundle for the gallery: the daemon's own
// importers read it and the OBJ into the same triangles, corners and
// materials.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.h"
#include "cli_test_helpers.h"
#include "glb_from_obj.h"
#include "image/png_codec.h"
#include "scene/gltf/gltf_import.h"
#include "scene/import/obj_import.h"

namespace toond::cli {
namespace {

using nlohmann::json;

// A textured quad (with normals; a polygon, so it is fanned), a plain
// triangle named by negative indices, a triangle whose material has only
// map_Kd, and a triangle before any usemtl. The MTL and its texture sit in
// folders, as exporters often put them.
constexpr const char* kObj = R"(mtllib mats/m.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 2 0.5 0
vt 0 0
vt 1 0
vt 1 1
vt 0.25 0.75
vn 0 0 1
f 1 2 5
usemtl textured
f 1/1/1 2/2/1 3/3/1 4/4/1
usemtl plain
f -4 -1 -3
usemtl painted
f 1/1 3/3 4/4
)";

constexpr const char* kMtl = R"(newmtl textured
Kd 0.5 0.25 1
map_Kd tex/c.png
newmtl plain
Ns 10
newmtl painted
map_Kd tex/C.PNG
)";

std::string tiny_png() {
  image::Image img;
  img.width = img.height = 2;
  img.rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  return image::encode_png(img);
}

BundleScan scan_of(const std::string& obj, const std::string& mtl) {
  return BundleScan{{{"model.obj", "model.obj", obj},
                     {"mats/m.mtl", "mats/m.mtl", mtl},
                     {"mats/tex/c.png", "mats/tex/c.png", tiny_png()}},
                    {}};
}

scene::Bundle bundle_of(const BundleScan& scan) {
  scene::Bundle bundle;
  for (const BundleFile& f : scan.files) bundle.add(f.name, f.content);
  return bundle;
}

json json_chunk(const std::string& glb) {
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return json::parse(glb.substr(20, length));
}

// Each triangle as its corners (position in double, texture coordinate,
// normal), rotated to start at its smallest corner so winding counts, with
// its material's colour and whether it is textured; sorted.
using Corner = std::array<double, 8>;
using Triangle = std::tuple<std::array<Corner, 3>, std::array<double, 3>, bool>;

std::vector<Triangle> triangles_of(const scene::Model& model) {
  const scene::Mesh& mesh = model.mesh;
  const auto rounded = [](double v) { return std::round(v * 1e6) / 1e6; };
  std::vector<Triangle> out;
  for (const scene::Submesh& s : mesh.submeshes) {
    const scene::Material& m = model.materials[static_cast<std::size_t>(s.material)];
    for (std::uint32_t i = s.first_index; i < s.first_index + s.index_count; i += 3) {
      std::array<Corner, 3> corners;
      for (std::uint32_t c = 0; c < 3; ++c) {
        const std::uint32_t v = mesh.indices[i + c];
        const glm::dvec3 p = mesh.origin + glm::dvec3(mesh.positions[v]);
        const glm::vec2 t = mesh.texcoords[v];
        const glm::vec3 n = mesh.normals[v];
        corners[c] = {rounded(p.x), rounded(p.y), rounded(p.z), rounded(t.x),
                      rounded(t.y), rounded(n.x), rounded(n.y), rounded(n.z)};
      }
      std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
      out.emplace_back(corners, std::array<double, 3>{rounded(m.diffuse.r), rounded(m.diffuse.g), rounded(m.diffuse.b)},
                       m.diffuse_texture >= 0);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(GlbFromObj, TheDaemonReadsTheSameTrianglesAndMaterialsAsFromTheObj) {
  const BundleScan scan = scan_of(kObj, kMtl);
  const std::string glb = glb_from_obj(scan);
  scene::Bundle glb_bundle;
  glb_bundle.add("model.glb", glb);
  const scene::Model from_glb = scene::import_gltf_bundle(glb_bundle, "model.glb");
  const scene::Model from_obj = scene::import_obj_bundle(bundle_of(scan));
  EXPECT_TRUE(from_glb.warnings.empty()) << from_glb.warnings.front();
  EXPECT_EQ(from_glb.mesh.triangle_count(), 5u);
  EXPECT_EQ(triangles_of(from_glb), triangles_of(from_obj));
  // A highlight where the OBJ's material has one, none where it says so.
  ASSERT_EQ(from_glb.materials.size(), from_obj.materials.size());
  for (std::size_t m = 0; m < from_obj.materials.size(); ++m) {
    EXPECT_EQ(from_glb.materials[m].matte, from_obj.materials[m].matte) << from_obj.materials[m].name;
  }
  const BundleScan matte = scan_of("mtllib mats/m.mtl\nusemtl flat\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                                   "newmtl flat\nKd 1 1 1\nKs 0 0 0\n");
  scene::Bundle matte_bundle;
  matte_bundle.add("model.glb", glb_from_obj(matte));
  EXPECT_TRUE(scene::import_gltf_bundle(matte_bundle, "model.glb").materials[0].matte);
}

// Per triangle (by its first corner's x), what its material says as the
// daemon reads it: colour, textured, highlight, opacity and alpha mode.
using Drawn = std::tuple<std::array<double, 3>, bool, bool, double, int>;

std::map<double, Drawn> drawn_materials(const scene::Model& model) {
  const scene::Mesh& mesh = model.mesh;
  std::map<double, Drawn> out;
  for (const scene::Submesh& s : mesh.submeshes) {
    const scene::Material& m = model.materials[static_cast<std::size_t>(s.material)];
    const auto rounded = [](double v) { return std::round(v * 1e6) / 1e6; };
    for (std::uint32_t i = s.first_index; i < s.first_index + s.index_count; i += 3) {
      double x = 1e9;
      for (std::uint32_t c = 0; c < 3; ++c)
        x = std::min(x, (mesh.origin + glm::dvec3(mesh.positions[mesh.indices[i + c]])).x);
      out[rounded(x)] = {{rounded(m.diffuse.r), rounded(m.diffuse.g), rounded(m.diffuse.b)},
                         m.diffuse_texture >= 0,
                         m.matte,
                         rounded(m.opacity),
                         static_cast<int>(m.alpha_mode)};
    }
  }
  return out;
}

// An OBJ whose MTL the old converter read its own way: a library name with
// a blank, a usemtl name with blanks, Kd out of range, illum 1, d and Tr, a
// map_Kd with options. Each triangle starts at its own x.
TEST(GlbFromObj, EachMaterialDrawsAsTheDaemonDrawsTheObjs) {
  std::string obj = "mtllib my mats.mtl\n";
  const std::vector<std::string> names = {"two words", "bright", "chalk", "glass", "veil", "painted", ""};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string x = std::to_string(2 * i);
    obj += "v " + x + " 0 0\nv " + x + ".5 0 0\nv " + x + " 1 0\n";
  }
  obj += "vt 0 0\nvt 1 0\nvt 0 1\n";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string v = std::to_string(3 * i + 1);
    obj += (names[i].empty() ? "" : "usemtl " + names[i] + "\n") + "f " + v + "/1 " + std::to_string(3 * i + 2) +
           "/2 " + std::to_string(3 * i + 3) + "/3\n";
  }
  // The last triangle follows `usemtl painted`: give it none of its own.
  obj.insert(obj.rfind("f "), "usemtl missing\n");
  const std::string mtl =
      "newmtl two words\nKd 0 0 1\nnewmtl bright\nKd 2 0.5 -1\nKs 1 1 1\nnewmtl chalk\nillum 1\n"
      "newmtl glass\nd 0.25\nnewmtl veil\nTr 0.75\nKd 0.2 0.4 0.6\nnewmtl painted\nmap_Kd -s 1 1 1 tex/C.PNG\n";
  const BundleScan scan{
      {{"model.obj", "model.obj", obj}, {"my mats.mtl", "my mats.mtl", mtl}, {"tex/c.png", "tex/c.png", tiny_png()}},
      {}};
  scene::Bundle glb_bundle;
  glb_bundle.add("model.glb", glb_from_obj(scan));
  const scene::Model from_glb = scene::import_gltf_bundle(glb_bundle, "model.glb");
  const scene::Model from_obj = scene::import_obj_bundle(bundle_of(scan));
  EXPECT_TRUE(from_glb.warnings.empty()) << from_glb.warnings.front();
  const std::map<double, Drawn> obj_drawn = drawn_materials(from_obj);
  ASSERT_EQ(obj_drawn.size(), names.size());
  EXPECT_EQ(drawn_materials(from_glb), obj_drawn);
  // The OBJ's own reading, so the agreement is not two defaults alike.
  EXPECT_EQ(std::get<0>(obj_drawn.at(0.0)), (std::array<double, 3>{0, 0, 1}));
  EXPECT_EQ(std::get<0>(obj_drawn.at(2.0)), (std::array<double, 3>{1, 0.5, 0}));
  EXPECT_TRUE(std::get<2>(obj_drawn.at(4.0)));
  EXPECT_EQ(std::get<3>(obj_drawn.at(6.0)), 0.25);
  EXPECT_EQ(std::get<3>(obj_drawn.at(8.0)), 0.25);
  EXPECT_TRUE(std::get<1>(obj_drawn.at(10.0)));
  EXPECT_EQ(std::get<0>(obj_drawn.at(12.0)), (std::array<double, 3>{0.8, 0.8, 0.8}));
}

TEST(GlbFromObj, APrimitivePerMaterialAndNormalsOnlyWhereEveryCornerHasOne) {
  const std::string glb = glb_from_obj(scan_of(kObj, kMtl));
  const json doc = json_chunk(glb);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  std::uint32_t total = 0;
  std::memcpy(&total, glb.data() + 8, 4);
  EXPECT_EQ(total, glb.size());

  const json& primitives = doc["meshes"][0]["primitives"];
  ASSERT_EQ(primitives.size(), 4u);  // none, textured, plain, painted
  std::vector<bool> normals, texcoords;
  for (const json& p : primitives) {
    normals.push_back(p["attributes"].contains("NORMAL"));
    texcoords.push_back(p["attributes"].contains("TEXCOORD_0"));
  }
  EXPECT_EQ(normals, (std::vector<bool>{false, true, false, false}));
  EXPECT_EQ(texcoords, (std::vector<bool>{false, true, false, true}));
  // One image, found by either spelling of its name, stored once.
  EXPECT_EQ(doc["images"].size(), 1u);
  EXPECT_EQ(doc["images"][0]["mimeType"], "image/png");
  // toond's colours for faces without a material and for map_Kd without Kd.
  const json& materials = doc["materials"];
  const std::vector<float> grey = materials[0]["pbrMetallicRoughness"]["baseColorFactor"];
  const std::vector<float> painted = materials[3]["pbrMetallicRoughness"]["baseColorFactor"];
  EXPECT_EQ(grey, (std::vector<float>{0.8f, 0.8f, 0.8f, 1.0f}));
  EXPECT_EQ(painted, (std::vector<float>{1.0f, 1.0f, 1.0f, 1.0f}));
  EXPECT_EQ(doc["nodes"][0]["translation"].get<std::vector<double>>(), (std::vector<double>{1.0, 0.5, 0.0}));
}

TEST(GlbFromObj, FarFromTheOriginKeepsTheObjsPrecision) {
  const std::string obj = "v 10000000.001 5 0\nv 10000000.002 5 0\nv 10000000.001 5.001 0\nf 1 2 3\n";
  const BundleScan scan{{{"far.obj", "far.obj", obj}}, {}};
  scene::Bundle glb_bundle;
  glb_bundle.add("far.glb", glb_from_obj(scan));
  EXPECT_EQ(triangles_of(scene::import_gltf_bundle(glb_bundle, "far.glb")),
            triangles_of(scene::import_obj_bundle(bundle_of(scan))));
}

TEST(GlbFromObj, AnObjWithoutFacesIsAUsageError) {
  const BundleScan scan{{{"points.obj", "points.obj", "v 0 0 0\nv 1 0 0\n"}}, {}};
  EXPECT_TRUE(cli_test::contains(cli_test::usage_error([&] { glb_from_obj(scan); }), "no faces"));
  EXPECT_TRUE(cli_test::contains(cli_test::usage_error([&] { glb_from_obj(BundleScan{}); }), "no OBJ"));
}

}  // namespace
}  // namespace toond::cli
