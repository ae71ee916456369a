// --render-threads: several render threads, each with its own GL context
// and GPU copies of the models, serving one queue.
#include <gtest/gtest.h>

#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "support/generated_models.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

// Concurrent requests land on either thread and get the bytes one thread
// would draw; a deleted model leaves both threads' GPU caches.
TEST(RenderThreads, TwoContextsDrawTheSameImagesAndBothForgetADeletedModel) {
  Daemon reference({}, {"--result-cache-mb", "0"});
  Daemon daemon({}, {"--render-threads", "2", "--result-cache-mb", "0"});
  auto reference_client = reference.client();
  auto client = daemon.client();
  const std::string obj = sphere_obj(32, 16);
  const std::string id = upload_obj_text(client, obj, "ball.obj");
  ASSERT_EQ(upload_obj_text(reference_client, obj, "ball.obj"), id) << "ids are content hashes";

  auto request = [](int yaw) {
    return nlohmann::json{{"width", 64}, {"height", 64}, {"msaa", 4}, {"camera", {{"yaw", yaw}}}};
  };
  std::map<int, std::string> expected;
  for (int yaw : {0, 90}) {
    auto res = post_json(reference_client, "/models/" + id + "/render", request(yaw));
    ASSERT_TRUE(res && res->status == 200);
    expected[yaw] = res->body;
  }
  std::mutex mutex;
  std::vector<std::pair<int, std::string>> answers;
  std::vector<std::thread> clients;
  for (int c = 0; c < 4; ++c) {
    clients.emplace_back([&, c] {
      auto mine = daemon.client();
      for (int i = 0; i < 4; ++i) {
        const int yaw = (c + i) % 2 == 0 ? 0 : 90;
        auto res = post_json(mine, "/models/" + id + "/render", request(yaw));
        std::lock_guard lock(mutex);
        answers.emplace_back(yaw, res && res->status == 200 ? res->body : std::string());
      }
    });
  }
  for (std::thread& t : clients) t.join();
  ASSERT_EQ(answers.size(), 16u);
  for (const auto& [yaw, body] : answers) EXPECT_TRUE(body == expected[yaw]) << "yaw " << yaw;

  auto res = client.Get("/metrics");
  ASSERT_TRUE(res && res->status == 200);
  // Sixteen renders in four concurrent streams: both threads drew, and each
  // holds its own copy of the sphere.
  EXPECT_EQ(sample_value(res->body, "toond_gpu_models_loaded"), 2) << res->body;

  ASSERT_EQ(client.Delete(("/models/" + id).c_str())->status, 200);
  const std::string after =
      scrape_when(client, [](const std::string& text) { return sample_value(text, "toond_gpu_models_loaded") == 0; });
  EXPECT_EQ(sample_value(after, "toond_gpu_models_loaded"), 0);
  EXPECT_EQ(sample_value(after, "toond_gpu_model_bytes"), 0);
}

}  // namespace
}  // namespace toond::test
