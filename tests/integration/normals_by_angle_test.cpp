// Files without normals through the HTTP upload: shaded by angle by
// default, `?smooth_angle` and `?up` change the import and the id, and bad
// values are a 400 naming the option.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "test_client.h"

namespace toond::test {
namespace {

using json = nlohmann::json;

const std::string kBareCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";

class NormalsByAngle : public SharedDaemonTest {
 protected:
  httplib::Result upload(const std::string& query, const std::string& obj = kBareCube) {
    auto client = daemon().client();
    httplib::MultipartFormDataItems items = {{"file", obj, "cube.obj", "text/plain"}};
    return client.Post("/models" + query, items);
  }

  // The distinct normals the normal layer shows where the cube covers it.
  std::size_t distinct_normals(const std::string& id) {
    auto client = daemon().client();
    const image::Image layer =
        render_ok(client, {{"model", id}, {"output", "normal"}, {"width", 128}, {"height", 128}});
    std::set<std::tuple<int, int, int>> seen;
    for (int y = 0; y < layer.height; ++y) {
      for (int x = 0; x < layer.width; ++x) {
        const std::uint8_t* p = layer.pixel(x, y);
        if (p[3] == 255) seen.insert({p[0], p[1], p[2]});
      }
    }
    return seen.size();
  }
};

// Six flat faces: the three in view show one normal each.
TEST_F(NormalsByAngle, ACubeWithoutNormalsHasFlatFaces) {
  auto res = upload("");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 201) << res->body;
  const json info = json::parse(res->body);
  EXPECT_FALSE(info.contains("smooth_angle"));
  EXPECT_EQ(distinct_normals(info.at("id")), 3u);
}

// 180 smooths every edge, as toond did before: a rounded cube of many
// normals, stored as another model that says so.
TEST_F(NormalsByAngle, ASmoothAngleOf180RoundsItAndIsAnotherModel) {
  auto flat = upload("");
  auto smooth = upload("?smooth_angle=180");
  ASSERT_TRUE(flat && smooth);
  ASSERT_TRUE(smooth->status == 200 || smooth->status == 201) << smooth->body;
  const json info = json::parse(smooth->body);
  EXPECT_NE(info.at("id"), json::parse(flat->body).at("id"));
  EXPECT_EQ(info.at("smooth_angle"), 180);
  EXPECT_GT(distinct_normals(info.at("id")), 100u);
  auto client = daemon().client();
  const json described = json::parse(client.Get("/models/" + info.at("id").get<std::string>())->body);
  EXPECT_EQ(described.at("smooth_angle"), 180);
}

TEST_F(NormalsByAngle, UpZTurnsATallFileUpright) {
  // 1 wide, 3 tall along +Z: once turned, 3 tall along +Y, so the default
  // view shows it taller than wide.
  const std::string tall =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 3\nv 1 0 3\nv 1 1 3\nv 0 1 3\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";
  auto res = upload("?up=z", tall);
  ASSERT_TRUE(res);
  ASSERT_TRUE(res->status == 200 || res->status == 201) << res->body;
  const json info = json::parse(res->body);
  EXPECT_EQ(info.at("up"), "z");
  auto client = daemon().client();
  const image::Image depth = render_ok(client, {{"model", info.at("id")},
                                                {"output", "normal"},
                                                {"width", 128},
                                                {"height", 128},
                                                {"camera", {{"yaw", 0}, {"pitch", 0}}}});
  int left = 128, right = -1, top = 128, bottom = -1;
  for (int y = 0; y < depth.height; ++y) {
    for (int x = 0; x < depth.width; ++x) {
      if (depth.pixel(x, y)[3] != 255) continue;
      left = std::min(left, x);
      right = std::max(right, x);
      top = std::min(top, y);
      bottom = std::max(bottom, y);
    }
  }
  EXPECT_GT(bottom - top, 2 * (right - left)) << "seen from the front the turned model stands upright";
}

TEST_F(NormalsByAngle, BadOptionsAreA400NamingThem) {
  for (const auto& [query, path] :
       {std::pair{"?smooth_angle=abc", "?smooth_angle"}, std::pair{"?smooth_angle=181", "?smooth_angle"},
        std::pair{"?smooth_angle=-1", "?smooth_angle"}, std::pair{"?up=x", "?up"}}) {
    auto res = upload(query);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << query << ": " << res->body;
    const json error = error_of(res);
    EXPECT_EQ(error.value("code", ""), "invalid_parameter") << query;
    EXPECT_EQ(error.value("path", ""), path) << query;
  }
}

}  // namespace
}  // namespace toond::test
