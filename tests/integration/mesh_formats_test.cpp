// One object in every format toond reads itself renders the same: a cube
// (flat everywhere: by angle, and by glTF's rule) and a wavy sheet (smooth
// by angle) written as OBJ without normals, binary and ASCII STL, and ASCII
// and binary PLY, uploaded over HTTP and rendered by the default request,
// colour and normal layer. (glTF's default material is white where OBJ's
// is 0.8 grey: the glb is held to the normal layer only.)
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "support/gltf_writer.h"
#include "support/mesh_file_writers.h"
#include "test_client.h"

namespace toond::test {
namespace {

using json = nlohmann::json;
using Files = std::vector<std::pair<std::string, std::string>>;

class MeshFormats : public SharedDaemonTest {
 protected:
  image::Image upload_and_render(const Files& files, const std::string& output) {
    auto client = daemon().client();
    httplib::MultipartFormDataItems items;
    for (const auto& [name, bytes] : files) items.push_back({"file", bytes, name, "application/octet-stream"});
    auto res = client.Post("/models", items);
    if (!res || (res->status != 200 && res->status != 201)) {
      ADD_FAILURE() << files.front().first << ": " << (res ? res->body : "no answer");
      return {};
    }
    const json info = json::parse(res->body);
    EXPECT_TRUE(info.at("warnings").empty()) << files.front().first << ": " << info.at("warnings");
    return render_ok(client, {{"model", info.at("id")}, {"width", 128}, {"height", 128}, {"output", output}});
  }

  void expect_alike(const Triangles& mesh, const std::vector<Files>& forms) {
    const Files reference_form = {{"m.obj", obj(mesh)}};
    for (const std::string output : {"color", "normal"}) {
      const image::Image reference = upload_and_render(reference_form, output);
      ASSERT_FALSE(reference.rgba.empty());
      for (const Files& form : forms) {
        const std::string& name = form.front().first;
        if (output == "color" && name.ends_with(".glb")) continue;
        const image::Image other = upload_and_render(form, output);
        ASSERT_EQ(other.rgba.size(), reference.rgba.size()) << name;
        // The same float positions and triangles: the same pixels.
        EXPECT_EQ(other.rgba, reference.rgba) << name << " renders unlike the OBJ (" << output << ")";
      }
    }
  }
};

TEST_F(MeshFormats, ACubeRendersAlikeFromEveryFormat) {
  const Triangles cube = cube_triangles();
  GltfPrimitive primitive;
  for (const glm::dvec3& p : cube.positions) primitive.positions.emplace_back(p);
  for (const auto& f : cube.faces) primitive.indices.insert(primitive.indices.end(), f.begin(), f.end());
  GltfDocument document;
  document.meshes = {{primitive}};
  expect_alike(cube, {{{"m.stl", binary_stl(cube)}},
                      {{"m.stl", ascii_stl(cube)}},
                      {{"m.ply", ply(cube, PlyForm::Ascii)}},
                      {{"m.ply", ply(cube, PlyForm::BinaryBig)}},
                      write_gltf(document, GltfForm::Glb)});
}

TEST_F(MeshFormats, ASmoothSheetRendersAlikeFromEveryFormatThatSmoothsByAngle) {
  const Triangles sheet = wavy_grid(24, 24);
  expect_alike(sheet, {{{"m.stl", binary_stl(sheet, "solid sheet")}},
                       {{"m.ply", ply(sheet, PlyForm::BinaryLittle)}}});
}

}  // namespace
}  // namespace toond::test
