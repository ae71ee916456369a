// --max-store-mb through real daemons: uploads past the bound let the least
// recently used models go (their ids then answer 404 unknown_model), a model
// rendered a moment ago stays, a model another replica is drawing stays, and
// two replicas sharing one data directory evict under load without ever
// answering with half a model.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "store_checks.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr std::uint64_t kTwoMiB = std::uint64_t{2} << 20;
const json kSmall = {{"width", 64}, {"height", 64}};

std::string id_of(const httplib::Result& res) { return json::parse(res->body).at("id"); }

int render_status(httplib::Client& client, const std::string& id) {
  auto res = post_json(client, "/models/" + id + "/render", kSmall);
  return res ? res->status : -1;
}

std::set<std::string> listed(httplib::Client& client) {
  std::set<std::string> ids;
  auto res = client.Get("/models");
  if (!res || res->status != 200) {
    ADD_FAILURE() << "GET /models failed";
    return ids;
  }
  const json body = json::parse(res->body);
  for (const json& m : body.at("models")) ids.insert(m.at("id").get<std::string>());
  return ids;
}

TEST(StoreBound, SixteenUploadsStayUnderTwoMegabytesAndTheModelRenderedAMomentAgoStays) {
  TOOND_REQUIRE_SHARED_MODELS();
  Daemon daemon({}, {"--max-store-mb", "2"});
  auto client = daemon.client();
  std::vector<std::string> ids;
  for (int i = 0; i < 16; ++i) {
    auto res = upload_teapot(client, i + 1);
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 201) << res->body;
    ids.push_back(id_of(res));
    // The first upload is rendered now and then: the last use that counts,
    // not the upload, keeps it.
    if (i % 4 == 3) {
      ASSERT_EQ(render_status(client, ids[0]), 200);
    }
  }

  const std::uint64_t on_disk = stored_file_bytes(daemon.data_dir());
  EXPECT_LT(on_disk, kTwoMiB);
  EXPECT_GT(on_disk, kTwoMiB * 3 / 4) << "the bound let more go than it needed";
  // Rendered a moment ago, uploaded first: still there.
  EXPECT_EQ(render_status(client, ids[0]), 200);
  EXPECT_EQ(render_status(client, ids[15]), 200);
  // The oldest upload never rendered is gone, with the usual answers.
  auto gone = post_json(client, "/models/" + ids[1] + "/render", kSmall);
  ASSERT_TRUE(gone);
  EXPECT_EQ(gone->status, 404);
  EXPECT_EQ(error_of(gone).value("code", ""), "unknown_model");
  auto described = client.Get(("/models/" + ids[1]).c_str());
  ASSERT_TRUE(described);
  EXPECT_EQ(described->status, 404);
  EXPECT_EQ(error_of(described).value("code", ""), "unknown_model");

  const std::set<std::string> kept = listed(client);
  EXPECT_TRUE(kept.count(ids[0]));
  EXPECT_FALSE(kept.count(ids[1]));
  std::set<std::string> on_store = store_entries_once_swept(daemon.data_dir());
  EXPECT_EQ(on_store, kept) << "a folder in the store is not a listed model";

  const std::string metrics = scrape_when(client, [](const std::string&) { return true; });
  EXPECT_EQ(sample_value(metrics, "toond_store_bytes"), static_cast<double>(on_disk));
  EXPECT_EQ(sample_value(metrics, "toond_store_max_bytes"), static_cast<double>(kTwoMiB));
  EXPECT_EQ(sample_value(metrics, "toond_models_stored"), static_cast<double>(kept.size()));
  EXPECT_EQ(sample_value(metrics, "toond_store_evictions_total"), static_cast<double>(16 - kept.size()));
  EXPECT_EQ(sample_value(metrics, "toond_store_refusals_total{reason=\"models_in_use\"}"), 0.0);
  EXPECT_TRUE(sample_value(metrics, "toond_store_volume_free_bytes"));

  auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  const json store = json::parse(health->body).at("store");
  EXPECT_EQ(store.at("models"), kept.size());
  EXPECT_EQ(store.at("bytes"), on_disk);
  EXPECT_EQ(store.at("max_bytes"), kTwoMiB);
  EXPECT_GT(store.at("used").get<double>(), 0.75);
  EXPECT_LT(store.at("used").get<double>(), 1.0);
  EXPECT_GT(store.at("volume").at("free_bytes").get<double>(), 0.0);
}

TEST(StoreBound, AModelLargerThanTheWholeBoundIsRefusedNamingTheFlag) {
  TOOND_REQUIRE_SHARED_MODELS();
  Daemon daemon({}, {"--max-store-mb", "2"});
  auto client = daemon.client();
  // The windmill bundle: 10.6 MB of OBJ, MTL and five 2048² JPEGs.
  auto res = upload_model_folder(client, shared_models_dir() / "windmill");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 413) << res->body;
  EXPECT_EQ(error_of(res).value("code", ""), "limit_exceeded");
  EXPECT_EQ(error_of(res).value("limit", ""), "--max-store-mb");
  EXPECT_TRUE(store_entries(daemon.data_dir()).empty());
  const std::string metrics = scrape_when(client, [](const std::string&) { return true; });
  EXPECT_EQ(sample_value(metrics, "toond_store_refusals_total{reason=\"larger_than_store\"}"), 1.0);
}

// Replica A draws X for seconds while uploads through replica B fill the
// store: X, the least recently used, is held by A's lease in its folder.
TEST(StoreBound, AModelAnotherReplicaIsDrawingIsNotLetGo) {
  TOOND_REQUIRE_SHARED_MODELS();
  const fs::path dir = make_temp_dir("toond-bound-held");
  {
    const std::vector<std::string> args = {"--max-store-mb", "1", "--render-timeout", "120", "--max-render-cost", "0"};
    Daemon a(dir, args);
    Daemon b(dir, args);
    auto ca = a.client();
    auto cb = b.client();
    auto up = upload_teapot(ca, 90);
    ASSERT_TRUE(up);
    const std::string x = id_of(up);

    int drawn = 0;
    Clock::time_point answered;
    std::thread drawing([&] {
      auto client = a.client();
      client.set_read_timeout(std::chrono::seconds(120));
      auto res = post_json(client, "/models/" + x + "/render",
                           {{"width", 2048}, {"height", 2048}, {"supersample", 2}, {"msaa", 4}});
      answered = Clock::now();
      drawn = res ? res->status : -1;
    });
    // The render holds X from the moment its lease is in X's folder.
    const fs::path leases = dir / "models" / x / "in-use";
    for (int i = 0; i < 500 && (!fs::exists(leases) || fs::is_empty(leases)); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    // Four teapots fit in 1 MiB; six more uploads would let X go first.
    for (int i = 0; i < 6; ++i) {
      auto res = upload_teapot(cb, i + 1);
      ASSERT_TRUE(res);
      EXPECT_EQ(res->status, 201) << res->body;
    }
    const auto uploaded = Clock::now();
    auto still = cb.Get(("/models/" + x).c_str());
    drawing.join();
    ASSERT_GT(answered, uploaded) << "the render ended before the uploads did; this test then shows nothing";
    EXPECT_EQ(drawn, 200);
    ASSERT_TRUE(still);
    EXPECT_EQ(still->status, 200) << "replica B let go of the model replica A was drawing";
    EXPECT_EQ(render_status(cb, x), 200);
    EXPECT_LE(stored_file_bytes(dir), std::uint64_t{1} << 20);
    EXPECT_TRUE(fs::is_empty(leases)) << "the finished render left its lease";
  }
  fs::remove_all(dir);
}

// Two replicas share one data directory and its bound. Each uploads a
// stream of models and renders what the other stored while both render one
// hot model: both let models go, every render answers a whole image or 404
// unknown_model (never half a model, never a 500), and once they are done
// the store is under its bound, with nothing half-deleted in it.
TEST(StoreBound, TwoReplicasOnOneStoreEvictUnderLoad) {
  TOOND_REQUIRE_SHARED_MODELS();
  const fs::path dir = make_temp_dir("toond-bound-replicas");
  {
    Daemon a(dir, {"--max-store-mb", "2"});
    Daemon b(dir, {"--max-store-mb", "2"});
    auto ca = a.client();
    const std::string hot = id_of(upload_teapot(ca, 0));

    std::mutex mutex;
    std::map<int, int> upload_statuses;
    std::map<int, int> render_statuses;
    std::vector<std::string> uploaded;
    std::atomic<int> uploaders_done{0};
    int hot_failures = 0;
    const auto count = [&](std::map<int, int>& statuses, int status) {
      std::lock_guard lock(mutex);
      ++statuses[status];
    };
    std::vector<std::thread> threads;
    const Daemon* replicas[] = {&a, &b};
    for (int r = 0; r < 2; ++r) {
      // Uploads through one replica; each new model rendered by the other.
      threads.emplace_back([&, r] {
        auto mine = replicas[r]->client();
        auto other = replicas[1 - r]->client();
        for (int i = 0; i < 12; ++i) {
          auto res = upload_teapot(mine, 1 + 2 * i + r);
          const int status = res ? res->status : -1;
          count(upload_statuses, status);
          if (status != 201) continue;
          const std::string id = id_of(res);
          {
            std::lock_guard lock(mutex);
            uploaded.push_back(id);
          }
          count(render_statuses, render_status(other, id));
        }
        ++uploaders_done;
      });
      // The hot model, over and over, and the models stored a while ago.
      threads.emplace_back([&, r] {
        auto client = replicas[r]->client();
        for (int n = 0; uploaders_done < 2; ++n) {
          const int status = render_status(client, hot);
          if (status != 200) {
            std::lock_guard lock(mutex);
            ++hot_failures;
          }
          std::string older;
          {
            std::lock_guard lock(mutex);
            if (!uploaded.empty()) older = uploaded[static_cast<std::size_t>(n) % uploaded.size()];
          }
          if (!older.empty()) count(render_statuses, render_status(client, older));
        }
      });
    }
    for (auto& t : threads) t.join();

    EXPECT_EQ(upload_statuses, (std::map<int, int>{{201, 24}}));
    EXPECT_EQ(hot_failures, 0);
    for (const auto& [status, n] : render_statuses) {
      EXPECT_TRUE(status == 200 || status == 404) << n << " renders answered " << status;
    }
    EXPECT_GT(render_statuses[404], 0) << "no render came after its model was let go";

    const std::set<std::string> entries = store_entries_once_swept(dir);
    for (const std::string& name : entries) EXPECT_FALSE(name.starts_with(".tmp-")) << name << " was left behind";
    EXPECT_LE(stored_file_bytes(dir), kTwoMiB);
    auto cb = b.client();
    EXPECT_EQ(listed(ca), entries);
    EXPECT_EQ(listed(cb), entries);
    EXPECT_TRUE(entries.count(hot));
    for (const std::string& id : entries) {
      EXPECT_EQ(render_status(ca, id), 200) << id;
      EXPECT_EQ(render_status(cb, id), 200) << id;
    }
    // Each replica let models go; between them, each of the 25 models that
    // is not kept, exactly once.
    const double by_a =
        counter_value(scrape_when(ca, [](const std::string&) { return true; }), "toond_store_evictions_total");
    const double by_b =
        counter_value(scrape_when(cb, [](const std::string&) { return true; }), "toond_store_evictions_total");
    EXPECT_GT(by_a, 0);
    EXPECT_GT(by_b, 0);
    EXPECT_EQ(by_a + by_b, static_cast<double>(25 - entries.size()));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace toond::test
