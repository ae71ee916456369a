// POST /models/{id}/render: the /render body with the model taken from the
// path, so a load balancer can hash on the model.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

class ModelRenderRoute : public SharedDaemonTest {};

const nlohmann::json kSmall = {{"width", 64}, {"height", 64}};

TEST_F(ModelRenderRoute, RendersTheModelInThePathExactlyLikeRenderWithModel) {
  auto client = daemon().client();
  const std::string id = upload_obj_text(client, sphere_obj(24, 12), "ball.obj");
  ASSERT_FALSE(id.empty());
  nlohmann::json with_model = kSmall;
  with_model["model"] = id;
  auto via_body = post_json(client, "/render", with_model);
  auto via_path = post_json(client, "/models/" + id + "/render", kSmall);
  ASSERT_TRUE(via_body && via_path);
  ASSERT_EQ(via_body->status, 200) << via_body->body;
  ASSERT_EQ(via_path->status, 200) << via_path->body;
  EXPECT_EQ(via_path->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(via_path->body, via_body->body);
  // And it is not the demo model the same body renders without a model.
  auto demo = post_json(client, "/render", kSmall);
  ASSERT_TRUE(demo);
  EXPECT_NE(demo->body, via_path->body);

  // A body naming the same model agrees with the path.
  auto agreeing = post_json(client, "/models/" + id + "/render", with_model);
  ASSERT_TRUE(agreeing);
  EXPECT_EQ(agreeing->status, 200);
  EXPECT_EQ(agreeing->body, via_body->body);
}

TEST_F(ModelRenderRoute, ABodyNamingAnotherModelIsRefused) {
  auto client = daemon().client();
  const std::string a = upload_obj_text(client, cube_obj(1.0), "a.obj");
  const std::string b = upload_obj_text(client, cube_obj(2.0), "b.obj");
  ASSERT_FALSE(a.empty() || b.empty());
  nlohmann::json body = kSmall;
  body["model"] = b;
  auto res = post_json(client, "/models/" + a + "/render", body);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  EXPECT_EQ(error_of(res)["code"], "model_mismatch");
  EXPECT_EQ(error_of(res)["path"], "/model");
}

TEST_F(ModelRenderRoute, AnUnknownModelIs404AndParametersAreStillValidated) {
  auto client = daemon().client();
  auto unknown = post_json(client, "/models/0123456789abcdef0123456789abcdef/render", kSmall);
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 404);
  EXPECT_EQ(error_of(unknown)["code"], "unknown_model");

  const std::string id = upload_obj_text(client, cube_obj(1.0), "c.obj");
  auto bad = post_json(client, "/models/" + id + "/render", {{"width", -3}});
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(error_of(bad)["path"], "/width");
}

// `toon render --model ID` goes through the model's path, so the CLI behind a
// load balancer keeps each model on one replica too.
TEST_F(ModelRenderRoute, TheCliRendersAStoredModelThroughItsPath) {
  auto client = daemon().client();
  const std::string id = upload_obj_text(client, sphere_obj(20, 10), "cli_ball.obj");
  ASSERT_FALSE(id.empty());
  const std::string series = request_series("POST", "/models/{id}/render", 200);
  const double before = counter_value(client.Get("/metrics")->body, series);
  const auto out = make_temp_dir("toon-cli-route") / "out.png";
  const ProcessResult run = run_process({TOON_BINARY, "render", "--server", daemon().url(), "--model", id, "--set",
                                         "width=40", "--set", "height=40", "-o", out.string()});
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string after =
      scrape_when(client, [&](const std::string& text) { return counter_value(text, series) >= before + 1; });
  EXPECT_EQ(counter_value(after, series), before + 1);
  std::ifstream file(out, std::ios::binary);
  const std::string png((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(image::decode_png(png).width, 40);
  std::filesystem::remove_all(out.parent_path());
}

}  // namespace
}  // namespace toond::test
