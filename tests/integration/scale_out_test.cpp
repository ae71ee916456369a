// Scale-out as deployed: three toond replicas sharing one data directory
// behind Debian's nginx, configured with the shipped docker/nginx snippets
// (hashing on the model id of /models/{id}/render, retry on the
// next replica when one is gone).
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <memory>
#include <thread>

#include "support/generated_models.h"
#include "support/nginx_balancer.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

constexpr int kReplicas = 3;
constexpr int kRendersPerModel = 2;  // round-robin would split even two
const nlohmann::json kParams = {{"width", 64}, {"height", 64}};

std::string scrape(const Daemon& replica) {
  auto client = replica.client();
  auto res = client.Get("/metrics");
  if (!res || res->status != 200) {
    ADD_FAILURE() << "GET /metrics on " << replica.url() << " failed";
    return {};
  }
  return res->body;
}

double balancer_renders_seen(const Daemon& replica) {
  return counter_value(scrape(replica), request_series("POST", "/models/{id}/render", 200));
}

// Renders `id` `times` times through the balancer and returns the index of
// the one replica whose /metrics counted them all (-1, with a failure, when
// they did not all land on one).
int replica_serving(httplib::Client& balancer, const std::string& id, int times,
                    const std::vector<std::unique_ptr<Daemon>>& replicas, const std::string& expected_png) {
  std::vector<double> before;
  for (const auto& r : replicas) before.push_back(r->running() ? balancer_renders_seen(*r) : 0);
  for (int i = 0; i < times; ++i) {
    auto res = post_json(balancer, "/models/" + id + "/render", kParams);
    if (!res || res->status != 200) {
      ADD_FAILURE() << "render of " << id << " through the balancer failed";
      return -1;
    }
    EXPECT_EQ(res->body, expected_png) << id;
  }
  // A replica counts a request just after sending its answer (the server's
  // logger hook), so wait until every render has been counted.
  std::vector<double> deltas(replicas.size(), 0.0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  for (;;) {
    double counted = 0;
    for (std::size_t i = 0; i < replicas.size(); ++i) {
      deltas[i] = replicas[i]->running() ? balancer_renders_seen(*replicas[i]) - before[i] : 0;
      counted += deltas[i];
    }
    if (counted >= times || std::chrono::steady_clock::now() > deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  int serving = -1;
  for (std::size_t i = 0; i < replicas.size(); ++i) {
    const double delta = deltas[i];
    if (delta == 0) continue;
    EXPECT_EQ(delta, times) << id << " was split across replicas";
    EXPECT_EQ(serving, -1) << id << " landed on more than one replica";
    serving = static_cast<int>(i);
  }
  EXPECT_NE(serving, -1) << "no replica counted the renders of " << id;
  return serving;
}

TEST(ScaleOut, ReplicasBehindNginxShareModelsKeepEachOnOneReplicaAndSurviveLosingOne) {
  const std::string nginx = NginxBalancer::find_nginx();
  if (nginx.empty()) GTEST_SKIP() << "nginx is not installed (scripts/install-deps.sh installs nginx-light)";

  const auto data_dir = make_temp_dir("toond-scale-out");
  {
    std::vector<std::unique_ptr<Daemon>> replicas;
    std::vector<std::string> upstreams;
    for (int i = 0; i < kReplicas; ++i) {
      replicas.push_back(std::make_unique<Daemon>(data_dir));
      upstreams.push_back(replicas.back()->url().substr(std::string("http://").size()));
    }
    NginxBalancer balancer_process(nginx, upstreams, TOOND_NGINX_SNIPPET_DIR);
    httplib::Client balancer(balancer_process.url());
    balancer.set_read_timeout(120);

    // Uploads go through the balancer, to whichever replica it picks.
    const std::vector<std::pair<std::string, std::string>> bundles = {
        {"ball.obj", sphere_obj(24, 12)},
        {"box.obj", cube_obj(1.0)},
        {"far.obj", sphere_obj(16, 8, 3.0, glm::dvec3(1e4, 0, 0))},
        {"small_box.obj", cube_obj(0.25, glm::dvec3(0, 5, 0))},
    };
    std::vector<std::string> ids;
    for (const auto& [name, obj] : bundles) {
      ids.push_back(upload_obj_text(balancer, obj, name));
      ASSERT_FALSE(ids.back().empty()) << name;
    }

    // Every replica lists every model and renders it, byte for byte like
    // the balancer does.
    std::map<std::string, std::string> png;
    for (const std::string& id : ids) {
      auto res = post_json(balancer, "/models/" + id + "/render", kParams);
      ASSERT_TRUE(res);
      ASSERT_EQ(res->status, 200) << res->body;
      png[id] = res->body;
    }
    for (const auto& replica : replicas) {
      auto client = replica->client();
      auto listed = client.Get("/models");
      ASSERT_TRUE(listed);
      EXPECT_EQ(nlohmann::json::parse(listed->body)["models"].size(), ids.size()) << replica->url();
      for (const std::string& id : ids) {
        auto res = post_json(client, "/models/" + id + "/render", kParams);
        ASSERT_TRUE(res);
        ASSERT_EQ(res->status, 200) << res->body;
        EXPECT_EQ(res->body, png[id]) << id << " on " << replica->url();
      }
    }

    // Counters lag their answers a little: let every render so far be
    // counted (once through the balancer, once on each replica, per model)
    // before counting per model.
    const double rendered = static_cast<double>(ids.size() * (1 + replicas.size()));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    double counted = 0;
    while (counted < rendered && std::chrono::steady_clock::now() < deadline) {
      counted = 0;
      for (const auto& replica : replicas) counted += balancer_renders_seen(*replica);
      if (counted < rendered) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_EQ(counted, rendered);

    // Each model's balancer renders land on one replica.
    std::map<std::string, int> owner;
    for (const std::string& id : ids) owner[id] = replica_serving(balancer, id, kRendersPerModel, replicas, png[id]);

    // Lose the replica serving the first model (killed, with nginx's
    // keep-alive connections to it open): every render through the balancer
    // still succeeds, and each model lands on one survivor.
    const int lost = owner[ids.front()];
    ASSERT_GE(lost, 0);
    replicas[static_cast<std::size_t>(lost)]->crash();
    for (const std::string& id : ids) {
      const int now = replica_serving(balancer, id, 2, replicas, png[id]);
      EXPECT_NE(now, lost);
      // A failed server is skipped: only the lost replica's models move.
      if (owner[id] != lost) {
        EXPECT_EQ(now, owner[id]) << id;
      }
    }
    if (HasFailure()) ADD_FAILURE() << "nginx error log:\n" << balancer_process.error_log();
  }
  std::filesystem::remove_all(data_dir);
}

}  // namespace
}  // namespace toond::test
