// Bad requests get a 4xx JSON error whose `path` points at the fault.
#include <gtest/gtest.h>

#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

class RequestErrors : public SharedDaemonTest {
 protected:
  json expect_error(const httplib::Result& res, int status, const std::string& code, const std::string& path) {
    if (!res) {
      ADD_FAILURE() << "no answer";
      return {};
    }
    EXPECT_EQ(res->status, status) << res->body;
    EXPECT_EQ(res->get_header_value("Content-Type"), "application/json");
    const json error = error_of(res);
    EXPECT_EQ(error.value("code", ""), code) << error;
    EXPECT_EQ(error.value("path", "?"), path) << error;
    EXPECT_FALSE(error.value("message", "").empty());
    return error;
  }
};

TEST_F(RequestErrors, MalformedJson) {
  auto client = daemon().client();
  auto res = client.Post("/render", "{\"width\": 12", "application/json");
  expect_error(res, 400, "malformed_json", "");
}

TEST_F(RequestErrors, BodyThatIsNotAnObject) {
  auto client = daemon().client();
  expect_error(client.Post("/render", "[1,2]", "application/json"), 400, "invalid_parameter", "");
}

TEST_F(RequestErrors, UnknownTopLevelField) {
  auto client = daemon().client();
  expect_error(post_json(client, "/render", {{"widht", 100}}), 400, "unknown_parameter", "/widht");
}

TEST_F(RequestErrors, UnknownNestedField) {
  auto client = daemon().client();
  const auto error = expect_error(post_json(client, "/render", {{"outline", {{"thickness", 3}}}}), 400,
                                  "unknown_parameter", "/outline/thickness");
  EXPECT_NE(error["message"].get<std::string>().find("thickness"), std::string::npos);
}

TEST_F(RequestErrors, UnknownFieldInsideAnArrayElement) {
  auto client = daemon().client();
  expect_error(post_json(client, "/render",
                         {{"lights", {{{"type", "directional"}}, {{"type", "directional"}, {"colour", {1, 1, 1}}}}}}),
               400, "unknown_parameter", "/lights/1/colour");
}

TEST_F(RequestErrors, OutOfRangeValue) {
  auto client = daemon().client();
  const auto error = expect_error(post_json(client, "/render", {{"outline", {{"width", 1000}}}}), 400,
                                  "invalid_parameter", "/outline/width");
  EXPECT_NE(error["message"].get<std::string>().find("64"), std::string::npos) << "names the limit";
}

TEST_F(RequestErrors, WrongType) {
  auto client = daemon().client();
  expect_error(post_json(client, "/render", {{"shading", {{"steps", "three"}}}}), 400, "invalid_parameter",
               "/shading/steps");
}

TEST_F(RequestErrors, ValueNotInEnum) {
  auto client = daemon().client();
  expect_error(post_json(client, "/render", {{"shading", {{"rounding", "truncate"}}}}), 400, "invalid_parameter",
               "/shading/rounding");
  expect_error(post_json(client, "/render", {{"msaa", 3}}), 400, "invalid_parameter", "/msaa");
}

TEST_F(RequestErrors, ArrayElementOutOfRange) {
  auto client = daemon().client();
  expect_error(post_json(client, "/render", {{"background", {0.5, 2, 0.5}}}), 400, "invalid_parameter",
               "/background/1");
}

TEST_F(RequestErrors, RenderBeyondTheSampleBudgetNamesTheKnobToLower) {
  auto client = daemon().client();
  const auto error =
      expect_error(post_json(client, "/render", {{"width", 4096}, {"height", 4096}, {"supersample", 2}, {"msaa", 8}}),
                   422, "limit_exceeded", "/msaa");
  EXPECT_NE(error["message"].get<std::string>().find("samples"), std::string::npos);
  expect_error(post_json(client, "/render", {{"width", 4096}, {"height", 4096}, {"supersample", 3}, {"msaa", 1}}), 422,
               "limit_exceeded", "/supersample");
}

TEST_F(RequestErrors, MissingModel) {
  auto client = daemon().client();
  expect_error(post_json(client, "/render", {{"model", "0123456789abcdef0123456789abcdef"}}), 404, "unknown_model",
               "/model");
}

TEST_F(RequestErrors, ModelIdThatIsNotAnId) {
  auto client = daemon().client();
  expect_error(post_json(client, "/render", {{"model", "../../etc"}}), 400, "invalid_parameter", "/model");
}

TEST_F(RequestErrors, UnknownModelOnTheModelRoutes) {
  auto client = daemon().client();
  expect_error(client.Get("/models/0123456789abcdef0123456789abcdef"), 404, "unknown_model",
               "/models/0123456789abcdef0123456789abcdef");
  expect_error(client.Delete("/models/0123456789abcdef0123456789abcdef"), 404, "unknown_model",
               "/models/0123456789abcdef0123456789abcdef");
}

TEST_F(RequestErrors, DaemonKeepsServingAfterErrors) {
  auto client = daemon().client();
  for (int i = 0; i < 5; ++i) post_json(client, "/render", {{"bogus", i}});
  const auto img = render_ok(client, {{"width", 32}, {"height", 32}});
  EXPECT_EQ(img.width, 32);
}

}  // namespace
}  // namespace toond::test
