#include <gtest/gtest.h>

#include "test_client.h"

namespace toond::test {
namespace {

class HealthAndSchema : public SharedDaemonTest {};

TEST_F(HealthAndSchema, HealthzReportsTheGlContext) {
  auto client = daemon().client();
  auto res = client.Get("/healthz");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  const auto body = nlohmann::json::parse(res->body);
  EXPECT_EQ(body["status"], "ok");
  for (const char* key : {"vendor", "renderer", "version"}) {
    ASSERT_TRUE(body["gl"].contains(key)) << key;
    EXPECT_FALSE(body["gl"][key].get<std::string>().empty()) << key;
  }
  // A core context of 4.3 or newer is what toond asks EGL for.
  const std::string version = body["gl"]["version"];
  EXPECT_GE(version.substr(0, 3), "4.3") << version;
}

TEST_F(HealthAndSchema, SchemaIsTheRenderParameterSchema) {
  auto client = daemon().client();
  auto res = client.Get("/schema");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  const auto schema = nlohmann::json::parse(res->body);
  EXPECT_EQ(schema["type"], "object");
  EXPECT_EQ(schema["additionalProperties"], false);
  for (const char* key :
       {"width", "height", "background", "camera", "lights", "ambient", "shading", "outline", "msaa", "model"}) {
    EXPECT_TRUE(schema["properties"].contains(key)) << key;
  }
  EXPECT_EQ(schema["properties"]["shading"]["properties"]["rounding"]["enum"],
            nlohmann::json({"ceil", "floor", "round"}));
}

TEST_F(HealthAndSchema, RootServesThePage) {
  auto client = daemon().client();
  auto res = client.Get("/");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_NE(res->get_header_value("Content-Type").find("text/html"), std::string::npos);
  // The page is a shell around its script module; the module drives /render.
  EXPECT_NE(res->body.find("src=\"/app.js\""), std::string::npos);
  auto script = client.Get("/app.js");
  ASSERT_TRUE(script);
  EXPECT_EQ(script->status, 200);
  EXPECT_NE(script->body.find("/render"), std::string::npos);
}

TEST_F(HealthAndSchema, UnknownRouteIsJson404) {
  auto client = daemon().client();
  auto res = client.Get("/no/such/route");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 404);
  EXPECT_EQ(error_of(res)["code"], "not_found");
}

}  // namespace
}  // namespace toond::test
