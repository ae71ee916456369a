// Runs the catalogue tests/bad_inputs/cases.jsonl against one real toond:
// every row is a hostile input and the answer it must get. After each row
// the daemon must still answer /healthz; rows that store a model render it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "image/png_codec.h"
#include "raw_http.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

struct Catalogue {
  std::vector<std::string> daemon_args;
  std::vector<json> rows;
};

const Catalogue& catalogue() {
  static const Catalogue loaded = [] {
    Catalogue c;
    // TOOND_BAD_INPUTS in the environment runs another catalogue of the same form.
    const char* chosen = std::getenv("TOOND_BAD_INPUTS");
    const std::string path = chosen && *chosen ? chosen : TOOND_BAD_INPUTS;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      json row = json::parse(line);
      if (row.contains("daemon_args")) {
        c.daemon_args = row["daemon_args"].get<std::vector<std::string>>();
      } else {
        c.rows.push_back(std::move(row));
      }
    }
    return c;
  }();
  return loaded;
}

std::string base64_decode(const std::string& text) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text) {
    const auto at = alphabet.find(c);
    if (at == std::string::npos) continue;  // '=' padding
    buffer = (buffer << 6) | static_cast<unsigned>(at);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xff);
    }
  }
  return out;
}

// A file's bytes: "text", "base64", or "prefix" + "repeat" × "times" + "suffix".
std::string content_of(const json& spec) {
  if (spec.contains("text")) return spec["text"];
  if (spec.contains("base64")) return base64_decode(spec["base64"]);
  std::string out = spec.value("prefix", "");
  const std::string repeat = spec.value("repeat", "");
  const auto times = spec.value("times", 0);
  out.reserve(out.size() + repeat.size() * static_cast<std::size_t>(times));
  for (int i = 0; i < times; ++i) out += repeat;
  return out + spec.value("suffix", "");
}

httplib::MultipartFormDataItems parts_of(const json& row) {
  httplib::MultipartFormDataItems items;
  for (const auto& file : row.value("files", json::array())) {
    items.push_back({"file", content_of(file), file["name"], "application/octet-stream"});
  }
  if (row.contains("params_text")) items.push_back({"params", row["params_text"], "", "application/json"});
  return items;
}

bool one_of(const json& expected, const json& actual) {
  if (expected.is_array()) {
    for (const auto& e : expected) {
      if (e == actual) return true;
    }
    return false;
  }
  return expected == actual;
}

class BadInputs : public ::testing::TestWithParam<json> {
 public:
  static void SetUpTestSuite() {
    // Files a confined importer must never read: if a bundle could reach
    // them, the material would turn up as "outside" without a warning.
    std::ofstream("/tmp/toond-bad-inputs-outside.mtl")
        << "newmtl outside\nKd 1 0 0\nmap_Kd toond-bad-inputs-outside.png\n";
    std::ofstream("/tmp/toond-bad-inputs-outside.png") << "not even a png";
    daemon_ = std::make_unique<Daemon>(std::filesystem::path{}, catalogue().daemon_args);
  }
  static void TearDownTestSuite() {
    daemon_.reset();
    std::filesystem::remove("/tmp/toond-bad-inputs-outside.mtl");
    std::filesystem::remove("/tmp/toond-bad-inputs-outside.png");
  }

 protected:
  static inline std::unique_ptr<Daemon> daemon_;
};

TEST_P(BadInputs, GetsTheCataloguedAnswer) {
  const json& row = GetParam();
  const json& expect = row["expect"];
  SCOPED_TRACE(row.value("why", ""));
  auto client = daemon_->client();
  const std::string route = row["route"];

  int status = 0;
  std::string body;
  if (route == "raw") {
    const RawAnswer answer = send_raw(daemon_->url(), row["raw"], 20, row.value("hang_up", false));
    status = answer.status;
    body = answer.body;
  } else {
    auto res = [&]() -> httplib::Result {
      if (route == "POST /models" && row.contains("files")) {
        return client.Post("/models" + row.value("query", std::string()), parts_of(row));
      }
      if (route == "POST /render multipart") {
        return client.Post("/render", parts_of(row));
      }
      std::string text;
      if (row.contains("body")) {
        text = row["body"].dump();
      } else if (row.contains("body_gen")) {
        text = content_of(row["body_gen"]);
      } else {
        text = row.value("body_text", "");
      }
      const std::string path = route.substr(route.find(' ') + 1);
      return client.Post(path, text, row.value("content_type", "application/json"));
    }();
    ASSERT_TRUE(res) << "no answer: " << httplib::to_string(res.error());
    status = res->status;
    body = res->body;
  }

  EXPECT_TRUE(one_of(expect["status"], status)) << "status " << status << ", body: " << body.substr(0, 400);
  const json answer = json::parse(body, nullptr, false);
  if (status >= 400 && status != 0) {
    ASSERT_FALSE(answer.is_discarded()) << "an error must be JSON: " << body.substr(0, 400);
    ASSERT_TRUE(answer.contains("error")) << body;
    const json& error = answer["error"];
    EXPECT_FALSE(error.value("message", "").empty()) << body;
    if (expect.contains("code")) {
      EXPECT_TRUE(one_of(expect["code"], error["code"])) << body;
    }
    if (expect.contains("path")) {
      EXPECT_EQ(error.value("path", "?"), expect["path"]) << body;
    }
    if (expect.contains("limit")) {
      EXPECT_EQ(error.value("limit", "?"), expect["limit"]) << body;
      EXPECT_NE(error.value("message", "").find(expect["limit"].get<std::string>()), std::string::npos) << body;
    }
    if (expect.contains("message")) {
      EXPECT_NE(error.value("message", "").find(expect["message"].get<std::string>()), std::string::npos) << body;
    }
  }
  if ((status == 200 || status == 201) && route == "POST /models") {
    ASSERT_FALSE(answer.is_discarded()) << body;
    if (expect.contains("warning")) {
      const std::string wanted = expect["warning"];
      bool found = false;
      for (const auto& w : answer["warnings"]) found = found || w.get<std::string>().find(wanted) != std::string::npos;
      EXPECT_TRUE(found) << "no warning mentioning '" << wanted << "': " << answer["warnings"];
    }
    for (const char* count : {"materials", "textures", "triangles"}) {
      if (expect.contains(count)) {
        EXPECT_EQ(answer[count], expect[count]) << count << " in " << body;
      }
    }
    if (expect.contains("files")) {
      EXPECT_EQ(answer["files"], expect["files"]) << body;
    }
    const std::string then = row.value("then", "");
    if (then == "render" || then == "render_if_stored") {
      const image::Image img = render_ok(client, {{"model", answer["id"]}, {"width", 64}, {"height", 64}});
      EXPECT_EQ(img.width, 64);
      EXPECT_EQ(img.height, 64);
    }
  } else if (status == 200 && route == "POST /render multipart") {
    const image::Image img = image::decode_png(body);
    EXPECT_GT(img.width, 0);
  } else if (row.value("then", "") == "render") {
    ADD_FAILURE() << "the row expects a stored model to render, but the upload answered " << status;
  }

  // Whatever the input, the daemon goes on serving.
  auto health = client.Get("/healthz");
  ASSERT_TRUE(health) << "daemon gone after " << row["name"];
  EXPECT_EQ(health->status, 200);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInputs, ::testing::ValuesIn(catalogue().rows),
                         [](const ::testing::TestParamInfo<json>& row) {
                           return row.param["name"].get<std::string>();
                         });

TEST(BadInputCatalogue, CoversEveryRoute) {
  std::set<std::string> routes;
  for (const auto& row : catalogue().rows) routes.insert(row["route"]);
  EXPECT_GE(catalogue().rows.size(), 80u);
  EXPECT_EQ(routes, (std::set<std::string>{"POST /models", "POST /render", "POST /render multipart", "raw"}));
}

}  // namespace
}  // namespace toond::test
