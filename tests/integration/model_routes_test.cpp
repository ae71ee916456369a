#include <gtest/gtest.h>

#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

class ModelRoutes : public SharedDaemonTest {};

TEST_F(ModelRoutes, SpotUploadsWithItsTextureAndTheSameBundleKeepsItsId) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  const auto folder = shared_models_dir() / "spot";
  auto first = upload_files(client, folder, {"spot.obj", "spot.mtl", "spot_texture.png"});
  ASSERT_TRUE(first);
  ASSERT_TRUE(first->status == 201 || first->status == 200) << first->body;
  const auto info = nlohmann::json::parse(first->body);
  EXPECT_EQ(info["triangles"], 5856);
  EXPECT_EQ(info["materials"], 1);
  EXPECT_EQ(info["textures"], 1);
  EXPECT_TRUE(info["warnings"].empty()) << info["warnings"];

  auto second = upload_files(client, folder, {"spot.obj", "spot.mtl", "spot_texture.png"});
  ASSERT_TRUE(second);
  EXPECT_EQ(second->status, 200) << "an already stored bundle answers 200";
  EXPECT_EQ(nlohmann::json::parse(second->body)["id"], info["id"]);

  auto listed = client.Get("/models");
  ASSERT_TRUE(listed);
  const auto models = nlohmann::json::parse(listed->body);
  bool found = false;
  for (const auto& m : models["models"]) found |= m["id"] == info["id"];
  EXPECT_TRUE(found);

  const std::string id = info["id"];
  auto described = client.Get(("/models/" + id).c_str());
  ASSERT_TRUE(described);
  EXPECT_EQ(described->status, 200);
  EXPECT_EQ(nlohmann::json::parse(described->body)["triangles"], 5856);
}

TEST_F(ModelRoutes, MultiMaterialModelReportsItsMaterialsAndTextures) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  auto res = upload_model_folder(client, shared_models_dir() / "windmill");
  ASSERT_TRUE(res);
  ASSERT_TRUE(res->status == 201 || res->status == 200) << res->body;
  const auto info = nlohmann::json::parse(res->body);
  EXPECT_EQ(info["materials"], 2);
  EXPECT_GE(info["textures"].get<int>(), 2);
  EXPECT_EQ(info["triangles"], 2722);
}

TEST_F(ModelRoutes, DifferentBytesGiveADifferentId) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  const auto folder = shared_models_dir() / "spot";
  auto with_texture = upload_files(client, folder, {"spot.obj", "spot.mtl", "spot_texture.png"});
  auto without_texture = upload_files(client, folder, {"spot.obj", "spot.mtl"});
  ASSERT_TRUE(with_texture && without_texture);
  EXPECT_NE(nlohmann::json::parse(with_texture->body)["id"], nlohmann::json::parse(without_texture->body)["id"]);
  // The missing texture is a warning, not an error.
  EXPECT_FALSE(nlohmann::json::parse(without_texture->body)["warnings"].empty());
}

TEST_F(ModelRoutes, DeleteRemovesTheModel) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  auto res =
      upload_files(client, shared_models_dir() / "kenney-space-craft", {"craft_speederA.obj", "craft_speederA.mtl"});
  ASSERT_TRUE(res);
  const std::string id = nlohmann::json::parse(res->body)["id"];
  auto deleted = client.Delete(("/models/" + id).c_str());
  ASSERT_TRUE(deleted);
  EXPECT_EQ(deleted->status, 200);
  auto gone = client.Get(("/models/" + id).c_str());
  ASSERT_TRUE(gone);
  EXPECT_EQ(gone->status, 404);
  auto render = post_json(client, "/render", {{"model", id}});
  ASSERT_TRUE(render);
  EXPECT_EQ(render->status, 404);
  EXPECT_EQ(error_of(render)["path"], "/model");
}

TEST(ModelStoreRestart, ModelIsStillListedAndRendersAfterARestart) {
  TOOND_REQUIRE_SHARED_MODELS();
  const auto dir = make_temp_dir("toond-restart");
  std::string id;
  {
    Daemon first(dir);
    auto client = first.client();
    auto res = upload_files(client, shared_models_dir() / "spot", {"spot.obj", "spot.mtl", "spot_texture.png"});
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 201) << res->body;
    id = nlohmann::json::parse(res->body)["id"];
    EXPECT_EQ(first.stop(), 0) << "SIGTERM ends toond cleanly";
  }
  {
    Daemon second(dir);
    auto client = second.client();
    auto listed = client.Get("/models");
    ASSERT_TRUE(listed);
    const auto models = nlohmann::json::parse(listed->body)["models"];
    ASSERT_EQ(models.size(), 1u);
    EXPECT_EQ(models[0]["id"], id);
    const auto img = render_ok(client, {{"model", id}, {"width", 64}, {"height", 64}});
    EXPECT_EQ(img.width, 64);
  }
  std::filesystem::remove_all(dir);
}

TEST_F(ModelRoutes, BundleWithoutObjIsRejectedNamingTheProblem) {
  auto client = daemon().client();
  httplib::MultipartFormDataItems items = {{"file", "newmtl x\nKd 1 0 0\n", "only.mtl", "text/plain"}};
  auto res = client.Post("/models", items);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422);
  const auto error = error_of(res);
  EXPECT_EQ(error["code"], "bad_bundle");
  EXPECT_NE(error["message"].get<std::string>().find(".obj"), std::string::npos) << error;
}

TEST_F(ModelRoutes, UploadThatIsNotMultipartIsRejected) {
  auto client = daemon().client();
  auto res = client.Post("/models", "v 0 0 0", "text/plain");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 415);
  EXPECT_EQ(error_of(res)["code"], "not_multipart");
}

TEST_F(ModelRoutes, UnsafeFileNameIsRejectedWithItsPath) {
  auto client = daemon().client();
  httplib::MultipartFormDataItems items = {{"file", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "m.obj", "text/plain"},
                                           {"file", "x", "../../etc/passwd", "text/plain"}};
  auto res = client.Post("/models", items);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  EXPECT_EQ(error_of(res)["path"], "../../etc/passwd");
}

}  // namespace
}  // namespace toond::test
