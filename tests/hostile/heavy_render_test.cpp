// One heavy request cannot stall the service: small uploads that would
// cover the frame tens of thousands of times are priced before drawing and
// refused, or drawn in a lane of their own and stopped at the deadline,
// while other clients' renders go on. Each against a real toond.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <iostream>
#include <string>
#include <thread>

#include "support/costly_models.h"
#include "support/daemon.h"
#include "support/heavy_inputs.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// Half a second after a long render was sent, five small renders (each at
// a yaw of its own, so none is answered from the cache) from `light`; how
// many were answered while the long one still drew.
int small_renders_answered_during(auto& light, const std::atomic<bool>& heavy_done) {
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  int answered = 0;
  for (int i = 0; i < 5; ++i) {
    auto res = post_json(light, "/render", {{"width", 128}, {"height", 128}, {"camera", {{"yaw", 7 + 13 * i}}}});
    EXPECT_TRUE(res);
    if (!res) continue;
    EXPECT_EQ(res->status, 200) << res->body;
    if (!heavy_done) ++answered;
  }
  return answered;
}

TEST(HeavyRender, ARepeatedTriangleUploadsAsOneWithAWarning) {
  Daemon daemon;
  auto client = daemon.client();
  const std::string obj = one_triangle_many_materials(100000);
  httplib::MultipartFormDataItems items = {{"file", obj, "repeats.obj", "text/plain"}};
  auto res = client.Post("/models", items);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 201) << res->body;
  const json info = json::parse(res->body);
  EXPECT_EQ(info.at("triangles"), 1);
  EXPECT_NE(info.at("warnings").dump().find("99999 triangles repeated the corners of another"), std::string::npos)
      << info.at("warnings");
  EXPECT_NEAR(info.at("cost").at("layers").get<double>(), 0.5, 1e-6);
  auto render = post_json(client, "/render", {{"model", info.at("id")}});
  ASSERT_TRUE(render);
  EXPECT_EQ(render->status, 200) << render->body;
}

TEST(HeavyRender, OneOverTheCostLimitIsRefusedBeforeDrawingWithTheFigures) {
  Daemon daemon;
  auto client = daemon.client();
  const std::string id = upload_obj_text(client, nearly_coincident_triangles(60000));
  ASSERT_FALSE(id.empty());
  auto res = post_json(client, "/render", {{"model", id}});
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 422) << res->body;
  const json error = error_of(res);
  EXPECT_EQ(error.value("code", ""), "limit_exceeded");
  EXPECT_EQ(error.value("limit", ""), "--max-render-cost");
  const std::string message = error.value("message", "");
  for (const char* part : {"Msamples", "--max-render-cost = 5000", "layers deep", "width and height"}) {
    EXPECT_NE(message.find(part), std::string::npos) << part << " in " << message;
  }
  // Nothing was drawn: the refusal counts as one, no render was observed.
  const std::string metrics = client.Get("/metrics")->body;
  EXPECT_EQ(counter_value(metrics, "toond_render_cost_refusals_total"), 1);
  EXPECT_EQ(counter_value(metrics, "toond_render_predicted_msamples_total"), 0);
  // The limit is one of those /healthz reports.
  const json health = json::parse(client.Get("/healthz")->body);
  EXPECT_EQ(health.at("limits").at("--max-render-cost"), 5000);
}

// With no cost limit the same model is drawn, in the long lane and in
// chunks: another client's small renders all answer while it draws, and
// it is stopped at --render-timeout with a 503 that says so.
TEST(HeavyRender, ALongRenderHoldsUpNoOtherClientAndStopsAtItsDeadline) {
  Daemon daemon({}, {"--max-render-cost", "0", "--render-timeout", "6"});
  auto heavy_client = daemon.client();
  const std::string id = upload_obj_text(heavy_client, nearly_coincident_triangles(60000));
  ASSERT_FALSE(id.empty());
  // Warm the short lane's thread (its programs), so the small renders
  // below time only themselves. (Each of them turns the camera to a yaw of
  // its own: none is the warm-up's default view, answered from the cache.)
  auto light_client = daemon.client();
  ASSERT_EQ(post_json(light_client, "/render", {{"width", 128}, {"height", 128}})->status, 200);

  std::atomic<bool> heavy_done{false};
  auto heavy = std::async(std::launch::async, [&] {
    auto res = post_json(heavy_client, "/render", {{"model", id}});
    heavy_done = true;
    return res;
  });
  const int answered_while_heavy_drew = small_renders_answered_during(light_client, heavy_done);
  EXPECT_EQ(answered_while_heavy_drew, 5) << "the small renders waited for the long one";

  auto res = heavy.get();
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 503) << res->body;
  EXPECT_TRUE(res->has_header("Retry-After"));
  const json error = error_of(res);
  EXPECT_EQ(error.value("code", ""), "render_aborted") << error;
  EXPECT_NE(error.value("message", "").find("--render-timeout"), std::string::npos) << error;
  const std::string metrics = light_client.Get("/metrics")->body;
  EXPECT_EQ(counter_value(metrics, "toond_render_aborts_total"), 1);
  EXPECT_EQ(counter_value(metrics, "toond_render_predicted_cost_msamples_count{lane=\"short\"}"), 6) << metrics;
  // The long lane is well after the abort: a long render that fits in
  // the deadline draws there normally.
  const std::string stack = upload_obj_text(heavy_client, stacked_triangles(800));
  auto after = post_json(heavy_client, "/render", {{"model", stack}});
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 200) << after->body;
  const std::string later = heavy_client.Get("/metrics")->body;
  EXPECT_EQ(counter_value(later, "toond_render_predicted_cost_msamples_count{lane=\"long\"}"), 1) << later;
}

// k³ cubes apart from one another, each a face a normal: 12 crease edges a
// cube, a hard-edged model of many crease edges.
std::string cube_field_obj(int k) {
  std::string obj;
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  int first = 1;
  for (int i = 0; i < k * k * k; ++i) {
    const int x = i % k, y = i / k % k, z = i / (k * k);
    for (int c = 0; c < 8; ++c) {
      obj += "v " + std::to_string(x + 0.75 * (c & 1)) + " " + std::to_string(y + 0.75 * (c >> 1 & 1)) + " " +
             std::to_string(z + 0.75 * (c >> 2 & 1)) + "\n";
    }
    for (const auto& f : faces) {
      obj += "f " + std::to_string(first + f[0]) + " " + std::to_string(first + f[1]) + " " +
             std::to_string(first + f[2]) + " " + std::to_string(first + f[3]) + "\n";
    }
    first += 8;
  }
  return obj;
}

// A hard-edged model of many crease edges (40,500 of them: 3,375 cubes),
// rendered large by default: its crease lines are priced by their edges
// and drawn in chunks of them in the long lane, like its meshes, so
// another client's small renders are answered while it draws.
TEST(HeavyRender, ManyCreaseEdgesHoldUpNoOtherClient) {
  Daemon daemon({}, {"--max-render-cost", "0", "--render-timeout", "20"});
  auto heavy_client = daemon.client();
  const std::string id = upload_obj_text(heavy_client, cube_field_obj(15));
  ASSERT_FALSE(id.empty());
  auto light_client = daemon.client();
  ASSERT_EQ(post_json(light_client, "/render", {{"width", 128}, {"height", 128}})->status, 200);
  std::atomic<bool> heavy_done{false};
  auto heavy = std::async(std::launch::async, [&] {
    auto res = post_json(heavy_client, "/render", {{"model", id}, {"width", 2048}, {"height", 2048}});
    heavy_done = true;
    return res;
  });
  const int answered_while_heavy_drew = small_renders_answered_during(light_client, heavy_done);
  EXPECT_EQ(answered_while_heavy_drew, 5) << "the small renders waited for the crease lines";
  auto res = heavy.get();
  ASSERT_TRUE(res);
  const std::string cost = res->get_header_value("X-Toond-Cost");
  std::cout << "cube field at 2048²: " << res->status << ", " << res->get_header_value("X-Toond-Passes") << ", " << cost
            << "\n";
  if (res->status == 200) {
    EXPECT_EQ(res->get_header_value("X-Toond-Passes"), "main,hull_outline,creases,resolve,readback");
    const auto at = cost.find("crease_edges=");
    ASSERT_NE(at, std::string::npos) << cost;
    EXPECT_EQ(std::stod(cost.substr(at + 13)), 40500.0) << cost;
  } else {
    EXPECT_EQ(res->status, 503) << res->body;
    EXPECT_EQ(error_of(res).value("code", ""), "render_aborted") << res->body;
  }
  const std::string metrics = light_client.Get("/metrics")->body;
  EXPECT_EQ(counter_value(metrics, "toond_render_predicted_cost_msamples_count{lane=\"long\"}"), 1) << metrics;
}

// A long render under the limit ends with its image, and says its price.
// A long sheet queues all its frames at once, more than the queue holds;
// they wait in the long lane, which is held to the capacity on its own, so
// another client's small renders are still taken (before, every one was a
// 503 `busy` until the sheet was done).
TEST(HeavyRender, ALongSheetsFramesDoNotFillTheQueueForOthers) {
  Daemon daemon({}, {"--max-render-cost", "0", "--long-render-cost", "20", "--queue", "2"});
  auto client = daemon.client();
  const std::string id = upload_obj_text(client, stacked_triangles(400));
  ASSERT_FALSE(id.empty());
  auto sheet = std::async(std::launch::async, [&] {
    auto own = daemon.client();
    return post_json(own, "/render", {{"model", id}, {"width", 256}, {"height", 256}, {"sheet", {{"frames", 24}}}});
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  int answered = 0;
  for (int i = 0; i < 5; ++i) {
    auto small = post_json(client, "/render", {{"width", 64}, {"height", 64}, {"camera", {{"yaw", 7 * i}}}});
    ASSERT_TRUE(small);
    EXPECT_EQ(small->status, 200) << small->body;
    answered += small->status == 200;
  }
  const auto long_sheet = sheet.get();
  ASSERT_TRUE(long_sheet);
  ASSERT_EQ(long_sheet->status, 200) << long_sheet->body;
  const std::string cost = long_sheet->get_header_value("X-Toond-Cost");
  EXPECT_GE(std::stod(cost.substr(5)), 20.0) << "the sheet must be priced into the long lane: " << cost;
  EXPECT_EQ(answered, 5);
}

TEST(HeavyRender, ALongRenderUnderTheDeadlineAnswersItsImageAndPrice) {
  Daemon daemon({}, {"--max-render-cost", "0", "--long-render-cost", "1"});
  auto client = daemon.client();
  const std::string id = upload_obj_text(client, stacked_triangles(200));
  ASSERT_FALSE(id.empty());
  auto res = post_json(client, "/render", {{"model", id}, {"width", 256}, {"height", 256}});
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const std::string cost = res->get_header_value("X-Toond-Cost");
  EXPECT_EQ(cost.rfind("cost=", 0), 0u) << cost;
  EXPECT_NE(cost.find("frames=1"), std::string::npos) << cost;
  const std::string metrics = client.Get("/metrics")->body;
  EXPECT_EQ(counter_value(metrics, "toond_render_predicted_cost_msamples_count{lane=\"long\"}"), 1);
}

// Every costly construct at the size of the reports, default
// request: an image or a clear refusal, and the daemon goes on.
TEST(HeavyRender, EveryCostlyConstructAnswersClearly) {
  Daemon daemon;
  auto client = daemon.client();
  for (const CostlyModel& model : costly_models()) {
    SCOPED_TRACE(model.what);
    const std::string id = upload_obj_text(client, model.obj(model.pathological_n));
    ASSERT_FALSE(id.empty());
    auto res = post_json(client, "/render", {{"model", id}});
    ASSERT_TRUE(res);
    if (res->status != 200) {
      const json error = error_of(res);
      const std::string code = error.value("code", "");
      EXPECT_TRUE((res->status == 422 && code == "limit_exceeded") || (res->status == 503 && code == "render_aborted"))
          << res->status << " " << res->body;
    }
    ASSERT_EQ(post_json(client, "/render", {{"width", 64}, {"height", 64}})->status, 200);
  }
}

// Each heavy import of the scaling tests, at its timing size, rendered by
// the default request too (not only imported): an image or a clear
// refusal. The times are printed, not judged (benchmarks judge times).
TEST(HeavyRender, EveryHeavyImportAlsoRendersClearly) {
  Daemon daemon;
  auto client = daemon.client();
  for (const HeavyInput& input : heavy_inputs()) {
    SCOPED_TRACE(input.what);
    httplib::MultipartFormDataItems items;
    const scene::Bundle bundle = input.make(input.base_n);
    for (const auto& [path, content] : bundle.files()) {
      items.push_back({"file", content, path, "application/octet-stream"});
    }
    const auto started = Clock::now();
    auto upload = client.Post("/models", items);
    ASSERT_TRUE(upload);
    ASSERT_TRUE(upload->status == 200 || upload->status == 201) << upload->body;
    const auto uploaded = Clock::now();
    auto res = post_json(client, "/render", {{"model", json::parse(upload->body).at("id")}});
    ASSERT_TRUE(res);
    const double upload_s = std::chrono::duration<double>(uploaded - started).count();
    const double render_s = std::chrono::duration<double>(Clock::now() - uploaded).count();
    std::cout << input.name << ": upload " << upload_s << " s, render " << res->status << " in " << render_s << " s, "
              << res->get_header_value("X-Toond-Cost") << "\n";
    if (res->status != 200) {
      const std::string code = error_of(res).value("code", "");
      EXPECT_TRUE((res->status == 422 && code == "limit_exceeded") || (res->status == 503 && code == "render_aborted"))
          << res->status << " " << res->body;
    }
  }
}

}  // namespace
}  // namespace toond::test
