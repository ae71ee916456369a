// A glTF upload may pick the scene it draws (POST /models?scene=N): the
// same files with another scene are another model, kept with its choice
// so a restarted daemon draws the same scene.
#include <gtest/gtest.h>

#include <fstream>

#include "image/png_codec.h"
#include "support/daemon.h"
#include "support/gltf_writer.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

// A cube; scene 0 holds it once, scene 1 twice, side by side.
std::string two_scene_glb() {
  GltfPrimitive cube;
  cube.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  cube.indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                  2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  GltfDocument doc;
  doc.meshes = {{cube}};
  GltfNode first;
  first.mesh = 0;
  GltfNode second = first;
  second.translation = glm::dvec3(3, 0, 0);
  doc.nodes = {first, second};
  doc.scene_roots = {0};
  GltfParts parts = build_gltf(doc);
  parts.json["scenes"].push_back({{"nodes", {0, 1}}});
  return pack_gltf(parts, GltfForm::Glb)[0].second;
}

httplib::Result upload(httplib::Client& client, const std::string& query, const std::string& bytes,
                       const std::string& name = "model.glb") {
  return client.Post("/models" + query,
                     httplib::MultipartFormDataItems{{"file", bytes, name, "application/octet-stream"}});
}

std::size_t differing_pixels(const image::Image& a, const image::Image& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); i += 4) {
    n += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2];
  }
  return n;
}

TEST(GltfScene, AnUploadPicksASceneByIndexAndARestartDrawsTheSameOne) {
  const std::filesystem::path data = make_temp_dir("toond-gltf-scene");
  const std::string glb = two_scene_glb();
  std::string default_id, second_id;
  image::Image default_image, second_image;
  const json look = {{"width", 96}, {"height", 96}};
  {
    Daemon daemon(data);
    auto client = daemon.client();
    auto plain = upload(client, "", glb);
    ASSERT_TRUE(plain && plain->status == 201) << (plain ? plain->body : "");
    const json plain_info = json::parse(plain->body);
    EXPECT_EQ(plain_info["triangles"], 12);
    EXPECT_FALSE(plain_info.contains("scene"));
    // The import report says how to pick the other scene.
    EXPECT_NE(plain_info["warnings"].dump().find("?scene=N"), std::string::npos) << plain_info["warnings"];

    auto picked = upload(client, "?scene=1", glb);
    ASSERT_TRUE(picked && picked->status == 201) << (picked ? picked->body : "");
    const json picked_info = json::parse(picked->body);
    EXPECT_EQ(picked_info["triangles"], 24);
    EXPECT_EQ(picked_info["scene"], 1);
    default_id = plain_info["id"];
    second_id = picked_info["id"];
    EXPECT_NE(default_id, second_id) << "another scene is another model";
    // The same choice again is the same model.
    auto again = upload(client, "?scene=1", glb);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->status, 200);
    EXPECT_EQ(json::parse(again->body)["id"], second_id);

    json params = look;
    params["model"] = default_id;
    default_image = render_ok(client, params);
    params["model"] = second_id;
    second_image = render_ok(client, params);
    EXPECT_GT(differing_pixels(default_image, second_image), 200u) << "the two scenes rendered alike";
    daemon.stop();
  }
  // A new daemon reads the model back from the store and imports it again
  // with the stored choice.
  Daemon restarted(data);
  auto client = restarted.client();
  auto info = client.Get("/models/" + second_id);
  ASSERT_TRUE(info && info->status == 200);
  EXPECT_EQ(json::parse(info->body)["scene"], 1);
  json params = look;
  params["model"] = second_id;
  EXPECT_EQ(differing_pixels(render_ok(client, params), second_image), 0u);
  restarted.stop();
  std::filesystem::remove_all(data);
}

TEST(GltfScene, TheCliUploadsWithTheSceneItIsGiven) {
  Daemon daemon;
  const std::filesystem::path dir = make_temp_dir("toond-cli-scene");
  std::ofstream(dir / "two.glb", std::ios::binary) << two_scene_glb();
  const ProcessResult cli =
      run_process({TOON_BINARY, "--server", daemon.url(), "upload", "--scene", "1", (dir / "two.glb").string()});
  EXPECT_EQ(cli.status, 0) << cli.err;
  const json answer = json::parse(cli.out, nullptr, false);
  ASSERT_TRUE(answer.is_object()) << cli.out;
  EXPECT_EQ(answer.value("scene", -1), 1) << cli.out;
  EXPECT_EQ(answer.value("triangles", 0), 24) << cli.out;
  std::filesystem::remove_all(dir);
}

TEST(GltfScene, ASceneThatIsNotThereOrNotAnIndexOrNotGltfIsRefused) {
  Daemon daemon;
  auto client = daemon.client();
  const std::string glb = two_scene_glb();

  auto missing = upload(client, "?scene=2", glb);
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 422) << missing->body;
  EXPECT_EQ(error_of(missing).value("code", ""), "bad_bundle");
  EXPECT_NE(error_of(missing).value("message", "").find("scene 2"), std::string::npos) << missing->body;

  for (const std::string bad : {"-1", "one", "", "1.5", "99999999999"}) {
    auto res = upload(client, "?scene=" + bad, glb);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << bad << ": " << res->body;
    EXPECT_EQ(error_of(res).value("code", ""), "invalid_parameter") << bad;
    EXPECT_EQ(error_of(res).value("path", ""), "?scene") << bad;
  }

  auto obj = upload(client, "?scene=0", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tri.obj");
  ASSERT_TRUE(obj);
  EXPECT_EQ(obj->status, 422) << obj->body;
  EXPECT_NE(error_of(obj).value("message", "").find("only glTF files have scenes"), std::string::npos) << obj->body;
  // Nothing was stored by the refused uploads.
  auto list = client.Get("/models");
  ASSERT_TRUE(list);
  EXPECT_TRUE(json::parse(list->body)["models"].empty()) << list->body;
}

}  // namespace
}  // namespace toond::test
