// The limit and access flags: documented defaults, parsing, --help.
#include <gtest/gtest.h>

#include "app/options.h"
#include "http/access_control.h"
#include "http/request_limits.h"

namespace toond::app {
namespace {

TEST(LimitOptions, DefaultsAreTheDocumentedOnes) {
  const Options o = parse_options({});
  EXPECT_EQ(o.host, "127.0.0.1");  // loopback unless told otherwise
  EXPECT_EQ(o.max_upload_bytes, 268435456u);
  EXPECT_EQ(o.limits.max_bundle_files, 256u);
  EXPECT_EQ(o.limits.import.max_vertices, 10000000u);
  EXPECT_EQ(o.limits.import.max_triangles, 10000000u);
  EXPECT_EQ(o.limits.import.max_texture_pixels, 67108864u);
  EXPECT_EQ(o.limits.render.max_output_pixels, 16777216u);
  EXPECT_EQ(o.limits.render.max_samples, 134217728u);
  EXPECT_EQ(o.limits.render.max_lights, 8u);
  EXPECT_EQ(o.limits.render.max_objects, 16u);
  EXPECT_EQ(o.limits.max_json_bytes, 1048576u);
  EXPECT_EQ(o.limits.max_json_depth, 32u);
  EXPECT_DOUBLE_EQ(o.limits.render.max_render_cost, 5000.0);
  EXPECT_DOUBLE_EQ(o.long_render_cost, 300.0);
  EXPECT_DOUBLE_EQ(o.render_timeout_s, 10.0);
  EXPECT_DOUBLE_EQ(o.limits.import.max_seconds, 30.0);
  EXPECT_TRUE(o.access.token.empty());
  EXPECT_TRUE(o.access.cors_origins.empty());
  // --help states each default as parsed above.
  for (const char* text :
       {"--max-bundle-files N   files in one upload (default 256)", "(default 10000000)", "(default 67108864",
        "(default 16777216", "(default 134217728", "(default 8)", "(default 16)", "(default 1048576)", "(default 32)",
        "--token T", "--max-import-seconds S", "nothing is stored (default 30)", "--cors-origin O", "TOOND_TOKEN",
        "--max-render-cost M", "(default 5000", "--long-render-cost M", "(default 300; 0: one lane)", "(default 10;"}) {
    EXPECT_NE(usage().find(text), std::string::npos) << text;
  }
}

TEST(LimitOptions, EachFlagSetsItsLimit) {
  const Options o = parse_options({"--max-bundle-files",
                                   "3",
                                   "--max-vertices",
                                   "100",
                                   "--max-triangles",
                                   "50",
                                   "--max-texture-pixels",
                                   "4096",
                                   "--max-output-pixels",
                                   "65536",
                                   "--max-samples",
                                   "100000",
                                   "--max-lights",
                                   "2",
                                   "--max-objects",
                                   "4",
                                   "--max-json-bytes",
                                   "2000",
                                   "--max-json-depth",
                                   "8",
                                   "--token",
                                   "abc",
                                   "--cors-origin",
                                   "*",
                                   "--render-timeout",
                                   "0.25",
                                   "--max-import-seconds",
                                   "2.5",
                                   "--max-render-cost",
                                   "300",
                                   "--long-render-cost",
                                   "0"});
  EXPECT_EQ(o.limits.max_bundle_files, 3u);
  EXPECT_EQ(o.limits.import.max_vertices, 100u);
  EXPECT_EQ(o.limits.import.max_triangles, 50u);
  EXPECT_EQ(o.limits.import.max_texture_pixels, 4096u);
  EXPECT_EQ(o.limits.render.max_output_pixels, 65536u);
  EXPECT_EQ(o.limits.render.max_samples, 100000u);
  EXPECT_EQ(o.limits.render.max_lights, 2u);
  EXPECT_EQ(o.limits.render.max_objects, 4u);
  EXPECT_EQ(o.limits.max_json_bytes, 2000u);
  EXPECT_EQ(o.limits.max_json_depth, 8u);
  EXPECT_EQ(o.access.token, "abc");
  EXPECT_EQ(o.access.cors_origins, std::vector<std::string>{"*"});
  EXPECT_DOUBLE_EQ(o.render_timeout_s, 0.25);
  EXPECT_DOUBLE_EQ(o.limits.import.max_seconds, 2.5);
  EXPECT_DOUBLE_EQ(o.limits.render.max_render_cost, 300.0);
  EXPECT_DOUBLE_EQ(o.long_render_cost, 0.0);
}

TEST(LimitOptions, BadValuesNameTheFlag) {
  for (const auto& args : std::vector<std::vector<std::string>>{{"--max-lights", "9"},
                                                                {"--max-objects", "0"},
                                                                {"--max-json-depth", "-1"},
                                                                {"--max-vertices", "lots"},
                                                                {"--token", ""},
                                                                {"--render-timeout", "0"},
                                                                {"--max-import-seconds", "0"},
                                                                {"--max-import-seconds", "soon"},
                                                                {"--max-samples"}}) {
    try {
      parse_options(args);
      ADD_FAILURE() << "accepted " << args[0];
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(args[0]), std::string::npos) << e.what();
    }
  }
}

TEST(JsonDepth, CountsOutsideStringsOnly) {
  EXPECT_EQ(http::json_nesting_depth(R"({"a":[1,{"b":2}]})", 100), 3u);
  EXPECT_EQ(http::json_nesting_depth(R"({"a":"[[[[{{{{"})", 100), 1u);
  EXPECT_EQ(http::json_nesting_depth(R"({"a":"\"[[["})", 100), 1u);
  EXPECT_EQ(http::json_nesting_depth(std::string(100000, '['), 10), 11u);  // stops early
}

TEST(BearerToken, MatchesOnlyTheExactToken) {
  EXPECT_TRUE(http::bearer_token_matches("Bearer abc", "abc"));
  EXPECT_TRUE(http::bearer_token_matches("bearer abc", "abc"));
  EXPECT_FALSE(http::bearer_token_matches("Bearer abcd", "abc"));
  EXPECT_FALSE(http::bearer_token_matches("Bearer ab", "abc"));
  EXPECT_FALSE(http::bearer_token_matches("Bearer ", ""));
  EXPECT_FALSE(http::bearer_token_matches("abc", "abc"));
  EXPECT_FALSE(http::bearer_token_matches("Basic abc", "abc"));
}

}  // namespace
}  // namespace toond::app
