// The toon CLI against a real daemon: exit codes, files written, errors.
#include <gtest/gtest.h>

#include <fstream>

#include "image/png_codec.h"
#include "support/image_checks.h"
#include "support/mesh_file_writers.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

class Cli : public SharedDaemonTest {
 protected:
  ProcessResult toon(std::vector<std::string> args, std::vector<std::string> env = {}) {
    args.insert(args.begin(), TOON_BINARY);
    return run_process(args, env);
  }
  std::filesystem::path out_dir() {
    static const auto dir = make_temp_dir("toon-cli");
    return dir;
  }
};

TEST_F(Cli, HealthPrintsTheGlRenderer) {
  const auto r = toon({"health", "--server", daemon().url()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("renderer"), std::string::npos) << r.out;
}

TEST_F(Cli, ServerFromTheEnvironmentAndBeforeTheVerb) {
  EXPECT_EQ(toon({"health"}, {"TOOND_URL=" + daemon().url()}).status, 0);
  EXPECT_EQ(toon({"--server", daemon().url(), "health"}).status, 0);
}

TEST_F(Cli, UploadThenRenderByIdWithSet) {
  TOOND_REQUIRE_SHARED_MODELS();
  const auto upload =
      toon({"upload", (shared_models_dir() / "spot" / "spot.obj").string(), "--server", daemon().url(), "--quiet"});
  ASSERT_EQ(upload.status, 0) << upload.err;
  std::string id = upload.out;
  while (!id.empty() && (id.back() == '\n' || id.back() == '\r')) id.pop_back();
  ASSERT_EQ(id.size(), 32u) << "--quiet prints the id alone: '" << upload.out << "'";

  // The CLI found the MTL and the texture the OBJ references.
  auto client = daemon().client();
  auto info = client.Get(("/models/" + id).c_str());
  ASSERT_TRUE(info);
  EXPECT_EQ(json::parse(info->body)["textures"], 1);

  const auto png = out_dir() / "spot.png";
  const auto render = toon({"render", "--model", id, "--set", "width=200", "--set", "height=120", "--set",
                            "outline.width=4", "-o", png.string(), "--server", daemon().url()});
  ASSERT_EQ(render.status, 0) << render.err;
  const auto img = image::decode_png(read_file(png));
  EXPECT_EQ(img.width, 200);
  EXPECT_EQ(img.height, 120);
  EXPECT_GT(coverage(foreground_mask(img)), 0.05);
}

TEST_F(Cli, RenderAPathUploadsItInOneCall) {
  TOOND_REQUIRE_SHARED_MODELS();
  const auto png = out_dir() / "dog.png";
  const auto r = toon({"--server", daemon().url(), "render",
                       (shared_models_dir() / "kenney-cube-pet-dog" / "animal-dog.obj").string(), "--set", "msaa=1",
                       "-o", png.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto img = image::decode_png(read_file(png));
  EXPECT_EQ(img.width, 512);
  EXPECT_GT(coverage(foreground_mask(img)), 0.05);
}

// The reference viewers' .m meshes go through the same verbs as OBJ files.
TEST_F(Cli, UploadsAndRendersADotMMesh) {
  const auto mesh = out_dir() / "tetra.m";
  {
    std::ofstream out(mesh);
    out << "# a tetrahedron\n"
           "Vertex 1 0 0 0\nVertex 2 1 0 0\nVertex 3 0 1 0\nVertex 4 0 0 1\n"
           "Face 1 1 3 2\nFace 2 1 2 4\nFace 3 1 4 3\nFace 4 2 3 4\n";
  }
  const auto upload = toon({"upload", mesh.string(), "--server", daemon().url()});
  ASSERT_EQ(upload.status, 0) << upload.err;
  const json info = json::parse(upload.out);
  EXPECT_EQ(info["triangles"], 4);
  EXPECT_EQ(info["files"], json::array({"tetra.m"}));

  const auto png = out_dir() / "tetra.png";
  const auto render = toon({"render", mesh.string(), "--set", "width=96", "--set", "height=96", "-o", png.string(),
                            "--server", daemon().url()});
  ASSERT_EQ(render.status, 0) << render.err;
  EXPECT_GT(coverage(foreground_mask(image::decode_png(read_file(png)))), 0.05);
}

// A binary STL is sent alone, and the upload options reach the import.
TEST_F(Cli, UploadsAnStlWithTheSmoothingAngleAndTheUpAxis) {
  const auto stl = out_dir() / "cube.stl";
  {
    std::ofstream out(stl, std::ios::binary);
    out << binary_stl(cube_triangles(), "solid exported");
  }
  const auto upload = toon({"upload", stl.string(), "--smooth-angle", "180", "--up", "z", "--server", daemon().url()});
  ASSERT_EQ(upload.status, 0) << upload.err;
  const json info = json::parse(upload.out);
  EXPECT_EQ(info["triangles"], 12);
  EXPECT_EQ(info["files"], json::array({"cube.stl"}));
  EXPECT_EQ(info["smooth_angle"], 180);
  EXPECT_EQ(info["up"], "z");
}

// An FBX character goes through the daemon's assimp helper and comes back
// with its clips; `toon info` shows them.
TEST_F(Cli, UploadsAnFbxCharacterWithItsClips) {
  const std::string fbx = (std::filesystem::path(TOOND_EXPORTED_DIR) / "blender" / "walker.fbx").string();
  const auto upload = toon({"upload", fbx, "--server", daemon().url()});
  ASSERT_EQ(upload.status, 0) << upload.err;
  const json info = json::parse(upload.out);
  EXPECT_EQ(info["files"], json::array({"walker.fbx"}));
  EXPECT_EQ(info["animation"]["joints"], 13);
  ASSERT_EQ(info["animation"]["clips"].size(), 2u);
  // In the order the file gives its takes.
  EXPECT_EQ(info["animation"]["clips"][0]["name"], "Walk");
  EXPECT_EQ(info["animation"]["clips"][1]["name"], "Idle");
}

// A game's player in a folder: its model names no skin, so the folder's
// images travel with it; --textures puts the mod's images on 3d_armor's
// three materials.
TEST_F(Cli, UploadsAGameFolderWithItsImagesAndTextures) {
  namespace fs = std::filesystem;
  const fs::path exported = TOOND_EXPORTED_DIR;
  const fs::path player = out_dir() / "player";
  fs::create_directories(player);
  fs::copy_file(exported / "minetest/character.b3d", player / "character.b3d", fs::copy_options::overwrite_existing);
  fs::copy_file(exported / "minetest/character.png", player / "character.png", fs::copy_options::overwrite_existing);
  auto upload = toon({"upload", player.string(), "--server", daemon().url()});
  ASSERT_EQ(upload.status, 0) << upload.err;
  json info = json::parse(upload.out);
  EXPECT_EQ(info["files"], json::array({"character.b3d", "character.png"}));
  EXPECT_EQ(info["textures"], 1);

  const fs::path armor = out_dir() / "armor";
  fs::create_directories(armor);
  fs::copy_file(exported / "3d_armor/3d_armor_character.b3d", armor / "3d_armor_character.b3d",
                fs::copy_options::overwrite_existing);
  fs::copy_file(exported / "minetest/character.png", armor / "character.png", fs::copy_options::overwrite_existing);
  fs::copy_file(exported / "3d_armor/3d_armor_trans.png", armor / "3d_armor_trans.png",
                fs::copy_options::overwrite_existing);
  upload = toon({"upload", armor.string(), "--textures", "character.png,3d_armor_trans.png,3d_armor_trans.png",
                 "--server", daemon().url()});
  ASSERT_EQ(upload.status, 0) << upload.err;
  info = json::parse(upload.out);
  EXPECT_EQ(info["texture_map"], json::array({"character.png", "3d_armor_trans.png", "3d_armor_trans.png"}));
  ASSERT_EQ(info["material_list"].size(), 3u);
  EXPECT_EQ(info["material_list"][0]["texture"], "character.png");
  EXPECT_EQ(info["material_list"][1]["texture"], "3d_armor_trans.png");
}

TEST_F(Cli, RenderWithParamsFileRendersTheDemo) {
  const auto params = out_dir() / "params.json";
  { std::ofstream(params) << json{{"width", 96}, {"height", 64}, {"shading", {{"steps", 4}}}}.dump(); }
  const auto png = out_dir() / "demo.png";
  const auto r = toon({"render", "--params", params.string(), "-o", png.string(), "--server", daemon().url()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto img = image::decode_png(read_file(png));
  EXPECT_EQ(img.width, 96);
  EXPECT_EQ(img.height, 64);
}

TEST_F(Cli, UnknownSetKeyFailsBeforeAnyRequest) {
  // No server at this address: a usage error must come first.
  const auto r =
      toon({"render", "--set", "outline.thickness=3", "-o", "/tmp/never.png", "--server", "http://127.0.0.1:9"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("outline.thickness"), std::string::npos) << r.err;
}

TEST_F(Cli, BadSetValueFails) {
  const auto r = toon({"render", "--set", "shading.steps=many", "-o", "/tmp/never.png"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("shading.steps"), std::string::npos) << r.err;
}

TEST_F(Cli, ServerSideRangeErrorIsReportedWithItsPath) {
  // 1000 is a number, so the CLI accepts the type; the range check names the path.
  const auto r =
      toon({"render", "--set", "outline.width=1000", "-o", (out_dir() / "x.png").string(), "--server", daemon().url()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("/outline/width"), std::string::npos) << r.err;
}

TEST_F(Cli, UnreachableServerIsANetworkError) {
  const auto r = toon({"health", "--server", "http://127.0.0.1:9"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("127.0.0.1:9"), std::string::npos) << r.err;
}

TEST_F(Cli, MissingOutputIsAUsageError) {
  const auto r = toon({"render", "--server", daemon().url()});
  EXPECT_EQ(r.status, 2);
}

TEST_F(Cli, HelpListsTheVerbs) {
  const auto r = toon({"--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* verb : {"upload", "render", "health", "--server", "--set"}) {
    EXPECT_NE(r.out.find(verb), std::string::npos) << verb;
  }
}

}  // namespace
}  // namespace toond::test
