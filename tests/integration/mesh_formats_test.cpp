// One object in every format toond reads itself renders the same: a cube
// (flat everywhere: by angle, and by glTF's rule) and a wavy sheet (smooth
// by angle) written as OBJ without normals, binary and ASCII STL, and ASCII
// and binary PLY, uploaded over HTTP and rendered by the default request,
// colour and normal layer. (glTF's default material is white where OBJ's
// is 0.8 grey: the glb is held to the normal layer only.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/gltf_writer.h"
#include "support/mesh_file_writers.h"
#include "support/shared_models.h"
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

// Files written by a real exporter (tests/exported/blender/make.py, Blender
// 3.4): its OBJ is Y-up, its binary STL and PLY Z-up, all without normals.
// Uploaded as users would (the Z-up ones with ?up=z) their normal layers
// agree everywhere (no pixel more than 8 levels off), and their colour
// renders in all but a few pixels of the crease lines: the OBJ's n-gons are
// fanned by the reader, Blender triangulates the others itself, and the
// edge pass follows the triangles' edges (at most 0.2 % of the image).
TEST_F(MeshFormats, BlenderExportsRenderAlike) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  auto client = daemon().client();
  const auto render = [&](const std::string& name, const std::string& query, const std::string& output) {
    httplib::MultipartFormDataItems items = {{"file", read_file(folder / name), name, "application/octet-stream"}};
    auto res = client.Post("/models" + query, items);
    EXPECT_TRUE(res && (res->status == 200 || res->status == 201)) << name << ": " << (res ? res->body : "");
    const json info = json::parse(res->body);
    EXPECT_EQ(info.at("triangles"), 200) << name;
    return render_ok(client, {{"model", info.at("id")}, {"width", 128}, {"height", 128}, {"output", output}});
  };
  for (const std::string output : {"color", "normal"}) {
    const image::Image obj_image = render("part.obj", "", output);
    ASSERT_FALSE(obj_image.rgba.empty());
    for (const std::string name : {"part.stl", "part.ply"}) {
      const image::Image other = render(name, "?up=z", output);
      ASSERT_EQ(other.rgba.size(), obj_image.rgba.size()) << name;
      std::size_t off = 0;  // pixels with a channel more than 8 levels off
      for (std::size_t i = 0; i < other.rgba.size(); i += 4) {
        for (std::size_t k = 0; k < 4; ++k) {
          if (std::abs(int(other.rgba[i + k]) - int(obj_image.rgba[i + k])) > 8) {
            ++off;
            break;
          }
        }
      }
      EXPECT_LE(off, output == "normal" ? 0u : 128u * 128u / 500u) << name << " " << output;
    }
  }
}

}  // namespace
}  // namespace toond::test
