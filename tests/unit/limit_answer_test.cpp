// The layers below HTTP report a limit by kind; the answer names the flag
// that sets it and words its message as every limit answer is worded.
#include <gtest/gtest.h>

#include <exception>
#include <string>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "http/error_response.h"
#include "scene/reading/import_limits.h"

namespace toond::http {
namespace {

using nlohmann::json;

template <typename E>
json error_of(const E& e, httplib::Response& res) {
  write_exception(res, std::make_exception_ptr(e));
  return json::parse(res.body).at("error");
}

TEST(ImportLimitAnswer, NamesTheFlagOfEachLimit) {
  struct Case {
    scene::ImportLimitError error;
    const char* flag;
    const char* message;
  };
  const Case cases[] = {
      {{"m.obj", scene::ImportLimit::Vertices, 5000, "m.obj has 5001 vertex positions, more than"},
       "--max-vertices",
       "m.obj has 5001 vertex positions, more than the limit --max-vertices = 5000"},
      {{"m.obj", scene::ImportLimit::Triangles, 5000, "m.obj has 5001 triangles, more than"},
       "--max-triangles",
       "m.obj has 5001 triangles, more than the limit --max-triangles = 5000"},
      {{"t.png", scene::ImportLimit::TexturePixels, 1048576,
        "t.png: the image is 2048x2048 = 4194304 pixels, more than"},
       "--max-texture-pixels",
       "t.png: the image is 2048x2048 = 4194304 pixels, more than the limit --max-texture-pixels = 1048576"},
      {{"", scene::ImportLimit::Seconds, 0.001, "the import took longer than",
        " and was abandoned while simplifying; nothing was stored"},
       "--max-import-seconds",
       "the import took longer than the limit --max-import-seconds = 0.001 s and was abandoned while simplifying; "
       "nothing was stored"},
  };
  for (const Case& c : cases) {
    httplib::Response res;
    const json error = error_of(c.error, res);
    EXPECT_EQ(res.status, 422);
    EXPECT_EQ(error.at("code"), "limit_exceeded");
    EXPECT_EQ(error.at("limit"), c.flag);
    EXPECT_EQ(error.at("message"), c.message);
    EXPECT_EQ(error.at("path"), c.error.file());
    // The importer's own message states the same facts without the flag.
    EXPECT_EQ(std::string(c.error.what()).find("--"), std::string::npos) << c.error.what();
  }
}

TEST(ImportLimitAnswer, TheGltfImportersLimitsAreNamedByHttpToo) {
  const scene::ImportLimitError e("m.glb", scene::ImportLimit::Triangles, 8,
                                  "m.glb: buffer view 2 decompresses to 27 indices, more than", " allows");
  EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
  httplib::Response res;
  const json error = error_of(e, res);
  EXPECT_EQ(error.at("limit"), "--max-triangles");
  EXPECT_EQ(error.at("message"),
            "m.glb: buffer view 2 decompresses to 27 indices, more than the limit --max-triangles = 8 allows");
}

}  // namespace
}  // namespace toond::http
