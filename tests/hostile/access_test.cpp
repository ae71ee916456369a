// --token / TOOND_TOKEN and --cors-origin against a real daemon.
#include <gtest/gtest.h>

#include <cstdlib>

#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

httplib::Headers bearer(const std::string& token) { return {{"Authorization", "Bearer " + token}}; }

void expect_unauthorized(const httplib::Result& res) {
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 401) << res->body;
  EXPECT_EQ(error_of(res).value("code", ""), "unauthorized") << res->body;
  EXPECT_EQ(res->get_header_value("WWW-Authenticate"), "Bearer realm=\"toond\"");
}

TEST(AccessToken, EveryRouteButHealthzNeedsIt) {
  Daemon daemon({}, {"--token", "s3cret-token"});
  auto client = daemon.client();
  auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);

  for (const char* path : {"/models", "/schema", "/presets", "/", "/models/0123456789abcdef0123456789abcdef"}) {
    SCOPED_TRACE(path);
    expect_unauthorized(client.Get(path));
    expect_unauthorized(client.Get(path, bearer("s3cret-tokem")));
    expect_unauthorized(client.Get(path, bearer("s3cret-token-and-more")));
    expect_unauthorized(client.Get(path, {{"Authorization", "Basic s3cret-token"}}));
  }
  expect_unauthorized(client.Post("/render", "{}", "application/json"));
  expect_unauthorized(client.Delete("/models/0123456789abcdef0123456789abcdef"));
  expect_unauthorized(client.Post("/models", httplib::MultipartFormDataItems{{"file", "v 0 0 0\n", "a.obj", ""}}));

  auto listed = client.Get("/models", bearer("s3cret-token"));
  ASSERT_TRUE(listed);
  EXPECT_EQ(listed->status, 200);
  client.set_default_headers(bearer("s3cret-token"));
  const image::Image img = render_ok(client, {{"width", 32}, {"height", 32}});
  EXPECT_EQ(img.width, 32);
}

TEST(AccessToken, TakenFromTheEnvironment) {
  ::setenv("TOOND_TOKEN", "from-env", 1);
  Daemon daemon;
  ::unsetenv("TOOND_TOKEN");
  auto client = daemon.client();
  expect_unauthorized(client.Get("/models"));
  auto ok = client.Get("/models", bearer("from-env"));
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->status, 200);
}

TEST(AccessToken, NoTokenByDefault) {
  Daemon daemon;
  auto client = daemon.client();
  auto res = client.Get("/models");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
}

TEST(Cors, OnlyTheConfiguredOriginIsAnswered) {
  Daemon daemon({}, {"--cors-origin", "https://app.example", "--token", "t0ken"});
  auto client = daemon.client();
  auto allowed = client.Get("/healthz", {{"Origin", "https://app.example"}});
  ASSERT_TRUE(allowed);
  EXPECT_EQ(allowed->get_header_value("Access-Control-Allow-Origin"), "https://app.example");
  EXPECT_EQ(allowed->get_header_value("Vary"), "Origin");
  auto other = client.Get("/healthz", {{"Origin", "https://evil.example"}});
  ASSERT_TRUE(other);
  EXPECT_FALSE(other->has_header("Access-Control-Allow-Origin"));

  // A preflight carries no credentials: answered without the token.
  auto preflight = client.Options("/render", {{"Origin", "https://app.example"},
                                              {"Access-Control-Request-Method", "POST"},
                                              {"Access-Control-Request-Headers", "authorization, content-type"}});
  ASSERT_TRUE(preflight);
  EXPECT_EQ(preflight->status, 204);
  EXPECT_EQ(preflight->get_header_value("Access-Control-Allow-Origin"), "https://app.example");
  EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Methods").find("POST"), std::string::npos);
  EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Headers").find("Authorization"), std::string::npos);

  // Errors carry the header too, so a page can read them.
  auto refused = client.Get("/models", {{"Origin", "https://app.example"}});
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 401);
  EXPECT_EQ(refused->get_header_value("Access-Control-Allow-Origin"), "https://app.example");
}

TEST(Cors, NoHeadersByDefault) {
  Daemon daemon;
  auto client = daemon.client();
  auto res = client.Get("/healthz", {{"Origin", "https://app.example"}});
  ASSERT_TRUE(res);
  EXPECT_FALSE(res->has_header("Access-Control-Allow-Origin"));
}

}  // namespace
}  // namespace toond::test
