// GET /metrics: Prometheus text that follows what the daemon did.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "support/generated_models.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

std::string scrape(httplib::Client& client) {
  auto res = client.Get("/metrics");
  if (!res || res->status != 200) {
    ADD_FAILURE() << "GET /metrics failed";
    return {};
  }
  EXPECT_EQ(res->get_header_value("Content-Type"), "text/plain; version=0.0.4; charset=utf-8");
  return res->body;
}

// A fresh daemon per test: counters start at zero.
TEST(MetricsRoute, CountsRequestsByRouteAndStatusAndTimesRendersAndPasses) {
  Daemon daemon;
  auto client = daemon.client();
  const std::string before = scrape(client);
  EXPECT_EQ(counter_value(before, request_series("POST", "/render", 200)), 0);
  EXPECT_EQ(sample_value(before, "toond_render_queue_depth"), 0);
  EXPECT_EQ(sample_value(before, "toond_models_stored"), 0);
  EXPECT_EQ(sample_value(before, "toond_gpu_models_loaded"), 0);
  EXPECT_EQ(sample_value(before, "toond_gpu_model_bytes"), 0);
  EXPECT_EQ(sample_value(before, "toond_result_cache_hits_total"), 0);
  // Unlabelled histograms are there, all zero, before their first event.
  for (const char* histogram : {"toond_render_seconds", "toond_import_seconds", "toond_import_bytes"}) {
    EXPECT_EQ(sample_value(before, std::string(histogram) + "_count"), 0) << histogram;
    EXPECT_EQ(sample_value(before, std::string(histogram) + "_bucket{le=\"+Inf\"}"), 0) << histogram;
  }

  const std::string id = upload_obj_text(client, sphere_obj(24, 12), "ball.obj");
  ASSERT_FALSE(id.empty());
  const nlohmann::json small = {{"width", 48}, {"height", 48}};
  // Different sizes: each is a render, none is answered by the result cache.
  ASSERT_EQ(post_json(client, "/render", small)->status, 200);
  ASSERT_EQ(post_json(client, "/render", {{"width", 40}, {"height", 40}})->status, 200);
  ASSERT_EQ(post_json(client, "/models/" + id + "/render", small)->status, 200);
  ASSERT_EQ(post_json(client, "/render", {{"width", -1}})->status, 400);
  ASSERT_EQ(client.Get("/models/0123456789abcdef0123456789abcdef")->status, 404);
  ASSERT_EQ(client.Get("/no/such/route")->status, 404);

  // Each request is counted just after its answer went out: wait for them.
  const std::vector<std::pair<std::string, double>> expected = {
      {request_series("POST", "/models", 201), 1},     {request_series("POST", "/render", 200), 2},
      {request_series("POST", "/render", 400), 1},     {request_series("POST", "/models/{id}/render", 200), 1},
      {request_series("GET", "/models/{id}", 404), 1}, {request_series("GET", "other", 404), 1},
  };
  const std::string after = scrape_when(client, [&](const std::string& text) {
    for (const auto& [series, count] : expected) {
      if (counter_value(text, series) < count) return false;
    }
    return true;
  });
  for (const auto& [series, count] : expected) EXPECT_EQ(counter_value(after, series), count) << series;
  EXPECT_GE(counter_value(after, request_series("GET", "/metrics", 200)), 1) << "the first scrape";

  // Three renders were made; the refused one is not a render.
  EXPECT_EQ(sample_value(after, "toond_render_seconds_count"), 3);
  EXPECT_EQ(sample_value(after, "toond_render_seconds_bucket{le=\"+Inf\"}"), 3);
  EXPECT_GT(sample_value(after, "toond_render_seconds_sum").value_or(0), 0);
  // Every render has a readback pass; its time is in the per-pass histogram.
  EXPECT_EQ(sample_value(after, "toond_render_pass_seconds_count{pass=\"readback\"}"), 3) << after;
  EXPECT_GT(sample_value(after, "toond_render_pass_seconds_sum{pass=\"readback\"}").value_or(0), 0);

  EXPECT_EQ(sample_value(after, "toond_models_stored"), 1);
  // The one upload was imported once: its time and its bytes.
  EXPECT_EQ(sample_value(after, "toond_import_seconds_count"), 1);
  EXPECT_GT(sample_value(after, "toond_import_seconds_sum").value_or(0), 0);
  EXPECT_EQ(sample_value(after, "toond_import_bytes_count"), 1);
  EXPECT_EQ(sample_value(after, "toond_import_bytes_sum"), static_cast<double>(sphere_obj(24, 12).size()));
  // The demo and the uploaded sphere are on the GPU now.
  EXPECT_EQ(sample_value(after, "toond_gpu_models_loaded"), 2);
  // 24×12 sphere: at least its 288 triangles' indices and a position per vertex.
  EXPECT_GT(sample_value(after, "toond_gpu_model_bytes").value_or(0), 288 * 3 * 4 + 24 * 13 * 12);

  // The same request again is a result-cache hit (the cache is on by default),
  // answered without a render.
  const double hits = sample_value(after, "toond_result_cache_hits_total").value_or(-1);
  ASSERT_EQ(post_json(client, "/render", small)->status, 200);
  const std::string cached = scrape(client);
  EXPECT_EQ(sample_value(cached, "toond_result_cache_hits_total"), hits + 1);
  EXPECT_EQ(sample_value(cached, "toond_render_seconds_count"), 3);
  EXPECT_GT(sample_value(cached, "toond_result_cache_bytes").value_or(0), 0);

  // Deleting the model drops its GPU copy.
  ASSERT_EQ(client.Delete(("/models/" + id).c_str())->status, 200);
  // A render queued after the delete's forget: the forget is done after it.
  ASSERT_EQ(post_json(client, "/render", {{"width", 32}, {"height", 32}})->status, 200);
  const std::string deleted = scrape(client);
  EXPECT_EQ(sample_value(deleted, "toond_models_stored"), 0);
  EXPECT_EQ(sample_value(deleted, "toond_gpu_models_loaded"), 1);
  EXPECT_LT(sample_value(deleted, "toond_gpu_model_bytes").value_or(0),
            sample_value(after, "toond_gpu_model_bytes").value_or(0));
}

}  // namespace
}  // namespace toond::test
