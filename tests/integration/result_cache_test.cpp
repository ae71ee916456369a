// The result cache and conditional requests: identical (model, parameters)
// are answered from memory, every render carries an ETag, and a client that
// already holds the image gets 304 Not Modified.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

const json kParams = {{"width", 96}, {"height", 96}, {"shading", {{"steps", 4}}}};

httplib::Result post_with_etag(httplib::Client& client, const json& body, const std::string& if_none_match) {
  httplib::Headers headers;
  if (!if_none_match.empty()) headers.emplace("If-None-Match", if_none_match);
  return client.Post("/render", headers, body.dump(), "application/json");
}

class ResultCache : public SharedDaemonTest {};

// A browser keeps its connection alive between slider moves. Each answer
// leaves in several writes; with Nagle's algorithm on, the last waited for
// the client's delayed ACK of the first: 40 ms on every request, 50 times
// a cache hit's own time. (Timed, but the margin is that stall itself.)
TEST_F(ResultCache, KeptAliveConnectionsGetAnswersWithoutWaitingForAcks) {
  auto client = daemon().client();
  client.set_keep_alive(true);
  client.set_tcp_nodelay(true);  // so any wait is the server's
  const json params = {{"width", 32}, {"height", 32}};
  ASSERT_EQ(post_json(client, "/render", params)->status, 200);
  std::vector<double> ms;
  for (int i = 0; i < 9; ++i) {
    const auto start = std::chrono::steady_clock::now();
    auto hit = post_json(client, "/render", params);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    ASSERT_TRUE(hit);
    ASSERT_EQ(hit->get_header_value("X-Toond-Cache"), "hit");
  }
  std::sort(ms.begin(), ms.end());
  EXPECT_LT(ms[ms.size() / 2], 20.0) << "median of 9 cache hits on one connection, ms";
}

TEST_F(ResultCache, IdenticalRequestsAreAnsweredFromMemory) {
  auto client = daemon().client();
  auto first = post_json(client, "/render", kParams);
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 200);
  EXPECT_FALSE(first->has_header("X-Toond-Cache"));
  EXPECT_NE(first->get_header_value("Server-Timing").find("main;dur="), std::string::npos);

  // Field order and explicit defaults do not matter: the key is the
  // completed, canonical parameter set.
  json same = json::parse(R"({"shading": {"rounding": "ceil", "steps": 4}, "height": 96, "width": 96})");
  auto second = post_json(client, "/render", same);
  ASSERT_TRUE(second);
  ASSERT_EQ(second->status, 200);
  EXPECT_EQ(second->get_header_value("X-Toond-Cache"), "hit");
  EXPECT_EQ(second->body, first->body);
  EXPECT_EQ(second->get_header_value("ETag"), first->get_header_value("ETag"));
  EXPECT_EQ(second->get_header_value("X-Toond-Passes"), first->get_header_value("X-Toond-Passes"));
  EXPECT_EQ(second->get_header_value("Server-Timing").rfind("cache;", 0), 0u);

  json other = kParams;
  other["shading"]["steps"] = 5;
  auto third = post_json(client, "/render", other);
  ASSERT_TRUE(third);
  EXPECT_FALSE(third->has_header("X-Toond-Cache"));
  EXPECT_NE(third->get_header_value("ETag"), first->get_header_value("ETag"));
}

TEST_F(ResultCache, IfNoneMatchGets304) {
  auto client = daemon().client();
  auto first = post_json(client, "/render", kParams);
  ASSERT_TRUE(first);
  const std::string etag = first->get_header_value("ETag");
  ASSERT_GE(etag.size(), 3u);
  EXPECT_EQ(etag.front(), '"');
  EXPECT_EQ(etag.back(), '"');

  auto again = post_with_etag(client, kParams, etag);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 304);
  EXPECT_TRUE(again->body.empty());
  EXPECT_EQ(again->get_header_value("ETag"), etag);

  auto listed = post_with_etag(client, kParams, "\"0000000000000000\", W/" + etag);
  ASSERT_TRUE(listed);
  EXPECT_EQ(listed->status, 304) << "one of a list, weak form";

  auto stale = post_with_etag(client, kParams, "\"0000000000000000\"");
  ASSERT_TRUE(stale);
  EXPECT_EQ(stale->status, 200);
  EXPECT_EQ(stale->body, first->body);
}

// Without the cache every request renders, and the ETag still names the
// bytes: renders are deterministic, so the tag is the same.
TEST(ResultCacheOff, EveryRequestRendersWithTheSameETag) {
  Daemon daemon({}, {"--result-cache-mb", "0"});
  auto client = daemon.client();
  auto first = post_json(client, "/render", kParams);
  auto second = post_json(client, "/render", kParams);
  ASSERT_TRUE(first && second);
  EXPECT_FALSE(second->has_header("X-Toond-Cache"));
  EXPECT_NE(second->get_header_value("Server-Timing").find("main;dur="), std::string::npos);
  EXPECT_EQ(second->get_header_value("ETag"), first->get_header_value("ETag"));
  auto conditional = post_with_etag(client, kParams, first->get_header_value("ETag"));
  ASSERT_TRUE(conditional);
  EXPECT_EQ(conditional->status, 304);
}

}  // namespace
}  // namespace toond::test
