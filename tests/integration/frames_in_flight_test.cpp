// --frames-in-flight 2: each render thread records the next queued frame
// before it reads back the last one. Concurrent clients and a sprite sheet
// (whose frames queue back to back) get the bytes a daemon reading every
// frame at once draws, and /metrics shows that frames did overlap.
#include <gtest/gtest.h>

#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "support/generated_models.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

// The overlap counter in the daemon's /metrics; nullopt when it is missing.
std::optional<double> frames_overlapped(httplib::Client& client) {
  const auto res = client.Get("/metrics");
  if (!res || res->status != 200) return std::nullopt;
  return sample_value(res->body, "toond_frames_overlapped_total");
}

TEST(FramesInFlight, ConcurrentRendersAndSheetsAreTheBytesOfTheSynchronousDaemon) {
  Daemon reference({}, {"--result-cache-mb", "0"});
  Daemon daemon({}, {"--frames-in-flight", "2", "--result-cache-mb", "0"});
  auto reference_client = reference.client();
  auto client = daemon.client();
  const std::string obj = sphere_obj(32, 16);
  const std::string id = upload_obj_text(client, obj, "ball.obj");
  ASSERT_EQ(upload_obj_text(reference_client, obj, "ball.obj"), id) << "ids are content hashes";

  std::vector<nlohmann::json> requests;
  for (int yaw : {0, 45, 90, 135}) {
    requests.push_back({{"width", 64}, {"height", 64}, {"camera", {{"yaw", yaw}}}});
  }
  requests.push_back({{"width", 48}, {"height", 48}, {"msaa", 1}, {"supersample", 2}});
  requests.push_back({{"width", 48}, {"height", 48}, {"output", "lines"}});
  requests.push_back({{"width", 48}, {"height", 48}, {"output", "normal"}});
  requests.push_back({{"width", 32}, {"height", 32}, {"sheet", {{"frames", 8}, {"columns", 4}}}});
  std::vector<std::string> expected;
  for (const nlohmann::json& request : requests) {
    auto res = post_json(reference_client, "/models/" + id + "/render", request);
    ASSERT_TRUE(res && res->status == 200) << request.dump();
    expected.push_back(res->body);
  }

  std::mutex mutex;
  std::vector<std::pair<std::size_t, std::string>> answers;
  std::vector<std::thread> clients;
  for (std::size_t c = 0; c < 4; ++c) {
    clients.emplace_back([&, c] {
      auto mine = daemon.client();
      for (std::size_t i = 0; i < requests.size(); ++i) {
        const std::size_t which = (c * 3 + i) % requests.size();
        auto res = post_json(mine, "/models/" + id + "/render", requests[which]);
        std::lock_guard lock(mutex);
        answers.emplace_back(which, res && res->status == 200 ? res->body : std::string());
      }
    });
  }
  for (std::thread& t : clients) t.join();
  ASSERT_EQ(answers.size(), 4 * requests.size());
  for (const auto& [which, body] : answers) {
    EXPECT_FALSE(body.empty()) << requests[which].dump();
    EXPECT_TRUE(body == expected[which]) << requests[which].dump();
  }
  // The frames really overlapped: each sheet's eight frames are queued at
  // once, so every one after the first is recorded while the one before
  // it is read back. The synchronous daemon never overlaps.
  const std::optional<double> overlapped = frames_overlapped(client);
  const std::optional<double> reference_overlapped = frames_overlapped(reference_client);
  ASSERT_TRUE(overlapped && reference_overlapped) << "toond_frames_overlapped_total is missing from /metrics";
  EXPECT_GE(*overlapped, 4 * 7);
  EXPECT_EQ(*reference_overlapped, 0);
}

}  // namespace
}  // namespace toond::test
