// Faults: SIGTERM drains the render in flight and exits 0; a render past
// --render-timeout is a 503; a GL error fails one request with a 500 and
// the daemon goes on; a lost GL context is replaced and models uploaded
// again; kill -9 during uploads loses no answered model and
// leaves no partial one; DELETE survives kill -9.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

TEST(Shutdown, SigtermFinishesTheRenderInFlightAndExitsZero) {
  Daemon daemon;
  int answer_status = 0;
  std::string answer_body;
  Clock::time_point answered;
  // Heavy enough on llvmpipe that it is still drawing when the signal comes.
  const json params = {{"width", 1024}, {"height", 1024}, {"supersample", 2}, {"msaa", 8}};
  std::thread request([&] {
    auto client = daemon.client();
    auto res = post_json(client, "/render", params);
    answered = Clock::now();
    if (res) {
      answer_status = res->status;
      answer_body = res->body;
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  const auto signalled = Clock::now();
  const int status = daemon.stop();  // SIGTERM, then waits for the exit
  request.join();
  EXPECT_EQ(status, 0);
  ASSERT_EQ(answer_status, 200) << answer_body;
  const image::Image img = image::decode_png(answer_body);
  EXPECT_EQ(img.width, 1024);
  EXPECT_EQ(img.height, 1024);
  EXPECT_GT(answered, signalled) << "the render ended before SIGTERM; this test then shows nothing";
}

TEST(Shutdown, SigtermWhenIdleExitsZero) {
  Daemon daemon;
  EXPECT_EQ(daemon.stop(), 0);
}

// Either the request stops waiting first or the render thread drops the
// job whose deadline passed in the queue: both answers name the limit.
TEST(RenderTimeout, PastItTheAnswerIs503WithRetryAfter) {
  Daemon daemon({}, {"--render-timeout", "0.001"});
  auto client = daemon.client();
  auto res = post_json(client, "/render", {{"width", 256}, {"height", 256}, {"msaa", 8}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 503) << res->body;
  EXPECT_TRUE(res->has_header("Retry-After"));
  const json error = error_of(res);
  EXPECT_EQ(error.value("code", ""), "deadline_exceeded");
  EXPECT_NE(error.value("message", "").find("--render-timeout"), std::string::npos) << error;
  auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

// An import past --max-import-seconds is abandoned with 422 naming the flag,
// and nothing of it is stored: the model list stays empty and the data
// folder holds no model. /healthz reports the limit.
TEST(ImportTimeLimit, PastItTheUploadIs422AndNothingIsStored) {
  const fs::path data = fs::temp_directory_path() / ("toond-import-limit-" + std::to_string(::getpid()));
  fs::remove_all(data);
  Daemon daemon(data, {"--max-import-seconds", "0.001"});
  auto client = daemon.client();
  const auto entries = [&] {
    std::set<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(data)) names.insert(entry.path().string());
    return names;
  };
  const std::set<std::string> before = entries();
  // 80,000 triangles: far more than a millisecond to import.
  httplib::MultipartFormDataItems items{{"file", sphere_obj(200, 200), "sphere.obj", "text/plain"}};
  auto res = client.Post("/models", items);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422) << res->body;
  const json error = error_of(res);
  EXPECT_EQ(error.value("code", ""), "limit_exceeded");
  EXPECT_EQ(error.value("limit", ""), "--max-import-seconds");
  EXPECT_NE(error.value("message", "").find("nothing was stored"), std::string::npos) << error;

  auto models = client.Get("/models");
  ASSERT_TRUE(models);
  EXPECT_EQ(json::parse(models->body).value("models", json::array()).size(), 0u) << models->body;
  EXPECT_EQ(entries(), before) << "the upload left files in " << data;

  auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_DOUBLE_EQ(json::parse(health->body)["limits"].value("--max-import-seconds", 0.0), 0.001) << health->body;
  fs::remove_all(data);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A shader that compiles but declares a uniform with another type than the
// renderer sets: glProgramUniform1f on an int is GL_INVALID_OPERATION, a
// real GL error in the id layer's pass, with no test hook in the daemon.
TEST(GlError, FailsThatRenderWith500AndTheDaemonGoesOn) {
  const fs::path dir = make_temp_dir("toond-glerror");
  for (const auto& entry : fs::directory_iterator(TOOND_SHADER_SOURCE_DIR)) {
    fs::copy_file(entry.path(), dir / entry.path().filename());
  }
  const std::string good = read_text(dir / "layer.frag");
  const std::string declaration = "uniform float u_layer_id;";
  ASSERT_NE(good.find(declaration), std::string::npos) << "layer.frag changed; pick another float uniform";
  std::string bad = good;
  bad.replace(bad.find(declaration), declaration.size(), "uniform int u_layer_id;");

  Daemon daemon({}, {"--shader-dir", dir.string()});
  auto client = daemon.client();
  const json params = {{"width", 64}, {"height", 64}, {"output", "id"}};
  render_ok(client, params);

  std::ofstream(dir / "layer.frag", std::ios::trunc) << bad;
  auto failed = post_json(client, "/render", params);
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->status, 500) << failed->body;
  const json error = error_of(failed);
  EXPECT_EQ(error.value("code", ""), "gpu_error") << error;
  EXPECT_NE(error.value("message", "").find("GL error"), std::string::npos) << error;

  auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  // A different file time than the broken one, so the reload notices.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::ofstream(dir / "layer.frag", std::ios::trunc) << good;
  const image::Image img = render_ok(client, params);
  EXPECT_EQ(img.width, 64);
  daemon.stop();
  fs::remove_all(dir);
}

// llvmpipe cannot lose its context, so the loss is simulated where a real
// one is detected (after the render, before its answer): everything from
// there on is the real recovery path.
TEST(LostContext, TheRenderFailsRetryablyAndTheNextOneUploadsTheModelToANewContext) {
  Daemon daemon({}, {"--simulate-gpu-reset", "3", "--result-cache-mb", "0"});
  auto client = daemon.client();
  const std::string id = upload_obj_text(client, sphere_obj(32, 16), "sphere.obj");
  const json params = {{"model", id}, {"width", 64}, {"height", 64}};
  auto render = [&] { return post_json(client, "/render", params); };
  auto first = render();
  ASSERT_TRUE(first && first->status == 200);
  auto second = render();
  ASSERT_TRUE(second && second->status == 200);
  EXPECT_EQ(second->body, first->body);

  auto lost = render();  // the third render: the context is lost
  ASSERT_TRUE(lost);
  EXPECT_EQ(lost->status, 503) << lost->body;
  EXPECT_EQ(lost->get_header_value("Retry-After"), "1");
  EXPECT_EQ(error_of(lost).value("code", ""), "gpu_reset") << lost->body;

  // A new context, the model uploaded to it again: the same bytes.
  auto again = render();
  ASSERT_TRUE(again);
  ASSERT_EQ(again->status, 200) << again->body;
  EXPECT_EQ(again->body, first->body);
  auto demo = post_json(client, "/render", {{"width", 64}, {"height", 64}});
  ASSERT_TRUE(demo);
  EXPECT_EQ(demo->status, 200);

  auto metrics = client.Get("/metrics");
  ASSERT_TRUE(metrics);
  EXPECT_NE(metrics->body.find("toond_gpu_context_resets_total 1\n"), std::string::npos);
  EXPECT_NE(metrics->body.find("toond_gpu_models_loaded 2\n"), std::string::npos)
      << "the sphere and the demo, both uploaded to the new context";
  EXPECT_EQ(daemon.stop(), 0);
}

std::string small_model(int n) {
  // Each model differs (so each gets its own id) and is big enough that
  // writing it takes a moment.
  std::ostringstream obj;
  obj << "# model " << n << "\n";
  for (int i = 0; i < 400; ++i) obj << "v " << i << " " << (i * 7 + n) % 13 << " " << (i % 5) << "\n";
  for (int i = 1; i + 2 <= 400; ++i) obj << "f " << i << " " << i + 1 << " " << i + 2 << "\n";
  return obj.str();
}

TEST(Durability, KillDuringUploadsLosesNoAnsweredModelAndKeepsNoPartialOne) {
  const fs::path data = make_temp_dir("toond-durable");
  std::set<std::string> answered;
  std::mutex mutex;
  {
    auto daemon = std::make_unique<Daemon>(data);
    std::atomic<bool> stop{false};
    std::atomic<int> next{0};
    std::vector<std::thread> uploaders;
    for (int t = 0; t < 4; ++t) {
      uploaders.emplace_back([&] {
        auto client = daemon->client();
        while (!stop) {
          const int n = next++;
          httplib::MultipartFormDataItems items = {{"file", small_model(n), "m.obj", ""}};
          auto res = client.Post("/models", items);
          if (res && res->status == 201) {
            std::lock_guard lock(mutex);
            answered.insert(json::parse(res->body)["id"].get<std::string>());
          }
        }
      });
    }
    while (true) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      std::lock_guard lock(mutex);
      if (answered.size() >= 8) break;
    }
    daemon->kill_hard();  // mid-upload: the uploaders are still sending
    stop = true;
    for (auto& t : uploaders) t.join();
  }
  ASSERT_GE(answered.size(), 8u);

  Daemon restarted(data);
  auto client = restarted.client();
  auto res = client.Get("/models");
  ASSERT_TRUE(res);
  const json models = json::parse(res->body)["models"];
  std::set<std::string> listed;
  for (const auto& m : models) listed.insert(m["id"].get<std::string>());
  for (const auto& id : answered) EXPECT_TRUE(listed.count(id)) << id << " was answered 201 but is gone";
  // Every listed model is whole: it renders.
  for (const auto& id : listed) {
    const image::Image img = render_ok(client, {{"model", id}, {"width", 32}, {"height", 32}});
    EXPECT_EQ(img.width, 32) << id;
  }
  // Every folder that is not an upload's temporary one is a listed model:
  // an interrupted upload never shows up half-written under its id.
  for (const auto& entry : fs::directory_iterator(data / "models")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(".tmp-", 0) == 0) continue;
    EXPECT_TRUE(listed.count(name)) << name << " is in the store but not a listed model";
  }
  restarted.stop();
  fs::remove_all(data);
}

TEST(Durability, DeleteSurvivesKill) {
  const fs::path data = make_temp_dir("toond-durable-delete");
  std::string kept;
  std::string deleted;
  {
    Daemon daemon(data);
    auto client = daemon.client();
    kept = upload_obj_text(client, small_model(1));
    deleted = upload_obj_text(client, small_model(2));
    auto res = client.Delete(("/models/" + deleted).c_str());
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 200);
    daemon.kill_hard();
  }
  Daemon restarted(data);
  auto client = restarted.client();
  auto gone = client.Get(("/models/" + deleted).c_str());
  ASSERT_TRUE(gone);
  EXPECT_EQ(gone->status, 404);
  auto still = client.Get(("/models/" + kept).c_str());
  ASSERT_TRUE(still);
  EXPECT_EQ(still->status, 200);
  restarted.stop();
  fs::remove_all(data);
}

}  // namespace
}  // namespace toond::test
