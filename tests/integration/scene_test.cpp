// Scenes: `objects` places several stored models, each by its transform,
// under one camera and one set of lights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "support/image_checks.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

class Scene : public SharedDaemonTest {
 protected:
  void SetUp() override {
    auto client = daemon().client();
    sphere_ = upload_obj_text(client, sphere_obj(64, 32), "sphere.obj");
    cube_ = upload_obj_text(client, cube_obj(), "cube.obj");
  }
  // A front view, no lines and no highlight, so coverage is the models' own.
  static json base() {
    return {{"width", 256},
            {"height", 256},
            {"msaa", 1},
            {"camera", {{"yaw", 0}, {"pitch", 0}}},
            {"outline", {{"enabled", false}}},
            {"specular", {{"enabled", false}}}};
  }
  static json object(const std::string& model, json transform = json::object()) {
    return {{"model", model}, {"transform", std::move(transform)}};
  }
  // Keeps a render for people to look at: TOOND_TEST_OUTPUT_DIR=/some/dir.
  static void keep(const Image& img, const std::string& name) {
    if (const char* dir = std::getenv("TOOND_TEST_OUTPUT_DIR")) {
      std::ofstream(std::filesystem::path(dir) / name, std::ios::binary) << image::encode_png(img);
    }
  }
  std::string sphere_, cube_;
};

std::size_t count_in_columns(const std::vector<bool>& mask, int width, int x0, int x1) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(width));
    n += mask[i] && x >= x0 && x < x1 ? 1 : 0;
  }
  return n;
}

// Connected regions (4-neighbourhood) of the mask.
std::size_t blob_count(std::vector<bool> mask, int width, int height) {
  std::size_t blobs = 0;
  std::vector<int> stack;
  for (int start = 0; start < width * height; ++start) {
    if (!mask[static_cast<std::size_t>(start)]) continue;
    ++blobs;
    stack.push_back(start);
    mask[static_cast<std::size_t>(start)] = false;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      const int x = p % width, y = p / width;
      const int next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      for (const auto& n : next) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= width || n[1] >= height) continue;
        const auto q = static_cast<std::size_t>(n[1] * width + n[0]);
        if (!mask[q]) continue;
        mask[q] = false;
        stack.push_back(static_cast<int>(q));
      }
    }
  }
  return blobs;
}

// First and last foreground pixel of row y ([-1, -1] for none).
std::pair<int, int> row_extent(const std::vector<bool>& mask, int width, int y, int x0 = 0, int x1 = -1) {
  if (x1 < 0) x1 = width;
  int first = -1, last = -1;
  for (int x = x0; x < x1; ++x) {
    if (!mask[static_cast<std::size_t>(y) * width + x]) continue;
    if (first < 0) first = x;
    last = x;
  }
  return {first, last};
}

TEST_F(Scene, TwoSpheresApartRenderAsTwoSeparateBlobs) {
  auto client = daemon().client();
  json params = base();
  params["objects"] = {object(sphere_, {{"translate", {-2, 0, 0}}}), object(sphere_, {{"translate", {2, 0, 0}}})};
  const Image img = render_ok(client, params);
  keep(img, "scene_two_spheres.png");
  const auto mask = foreground_mask(img);
  const std::size_t left = count_in_columns(mask, 256, 0, 128);
  const std::size_t right = count_in_columns(mask, 256, 128, 256);
  EXPECT_GT(left, 2000u);
  EXPECT_GT(right, 2000u);
  EXPECT_NEAR(static_cast<double>(left) / static_cast<double>(right), 1.0, 0.05) << "mirror images";
  // Scene x -1..1 lies between them: the middle columns are empty.
  EXPECT_EQ(count_in_columns(mask, 256, 120, 136), 0u) << "a gap between the two";
  // The camera framed both: neither is cut by the image border.
  EXPECT_EQ(count_in_columns(mask, 256, 0, 1) + count_in_columns(mask, 256, 255, 256), 0u);
}

TEST_F(Scene, DoubleScaleCoversFourTimesThePixelsAtAFixedDistance) {
  auto client = daemon().client();
  json params = base();
  params["camera"]["distance"] = 12;
  params["objects"] = {object(sphere_)};
  const double one = coverage(foreground_mask(render_ok(client, params)));
  params["objects"] = {object(sphere_, {{"scale", 2}})};
  const double two = coverage(foreground_mask(render_ok(client, params)));
  // Perspective makes it a little over 4 (silhouette angle asin(r/d)).
  EXPECT_NEAR(two / one, 4.09, 0.2);
  // A per-axis scale: twice as wide only, about twice the pixels.
  params["objects"] = {object(sphere_, {{"scale", {2, 1, 1}}})};
  const double wide = coverage(foreground_mask(render_ok(client, params)));
  EXPECT_NEAR(wide / one, 2.0, 0.15);
}

TEST_F(Scene, RotationTurnsTheModel) {
  auto client = daemon().client();
  json params = base();
  params["camera"]["distance"] = 8;
  params["objects"] = {object(cube_)};
  const Image square = render_ok(client, params);
  params["objects"] = {object(cube_, {{"rotate", {0, 45, 0}}})};
  const Image turned = render_ok(client, params);
  keep(turned, "scene_cube_rotated.png");
  const auto [a0, a1] = row_extent(foreground_mask(square), 256, 128);
  const auto [b0, b1] = row_extent(foreground_mask(turned), 256, 128);
  ASSERT_GE(a0, 0);
  ASSERT_GE(b0, 0);
  // Face on, the cube's front face (2 wide, 7 from the eye) spans it;
  // turned 45°, the side edges (2√2 apart, 8 from the eye) do:
  // (2√2 / 8) / (2 / 7) = 1.237.
  const double ratio = static_cast<double>(b1 - b0 + 1) / static_cast<double>(a1 - a0 + 1);
  EXPECT_NEAR(ratio, 1.237, 0.03);
  // Turned, two faces show, in two different shades.
  EXPECT_GE(dominant_colours(turned, foreground_mask(turned), 0.2), 2u);
}

TEST_F(Scene, OneObjectWithoutTransformRendersExactlyLikeTheModel) {
  auto client = daemon().client();
  // Everything on: lines, highlight, rim, shadows and floor.
  json params = {
      {"width", 200},
      {"height", 160},
      {"rim", {{"enabled", true}}},
      {"shadows", {{"enabled", true}}},
      {"floor", {{"enabled", true}}},
      {"outline", {{"method", {"hull", "edges"}}}},
      {"lights",
       {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}}, {{"type", "point"}, {"position", {1.5, 1, 2}}}}}};
  json single = params;
  single["model"] = sphere_;
  json scene = params;
  scene["objects"] = {object(sphere_)};
  const Image a = render_ok(client, single);
  const Image b = render_ok(client, scene);
  EXPECT_TRUE(a.rgba == b.rgba) << "bit for bit";
  scene["objects"] = {object(sphere_, {{"translate", {0, 0, 0}}, {"rotate", {0, 0, 0}}, {"scale", 1}})};
  EXPECT_TRUE(render_ok(client, scene).rgba == a.rgba) << "explicit identity";
}

TEST_F(Scene, FarFromTheOriginRendersLikeAtTheOrigin) {
  auto client = daemon().client();
  json params = base();
  params["outline"] = {{"enabled", true}};
  params["lights"] = {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}},
                      {{"type", "point"}, {"position", {0, 0, 2}}, {"radius", 6}}};
  params["objects"] = {object(sphere_, {{"translate", {-2, 0, 0}}}), object(sphere_, {{"translate", {2, 0, 0}}})};
  const Image near = render_ok(client, params);
  const double d = 1e5;
  params["lights"][1]["position"] = {d, d, d + 2};
  params["objects"] = {object(sphere_, {{"translate", {d - 2, d, d}}}),
                       object(sphere_, {{"translate", {d + 2, d, d}}})};
  const Image far = render_ok(client, params);
  keep(far, "scene_far.png");
  std::size_t differ = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) differ += rgb_at(near, x, y) != rgb_at(far, x, y) ? 1 : 0;
  EXPECT_LE(static_cast<double>(differ) / (256.0 * 256.0), 0.005) << differ << " pixels differ";
  EXPECT_GT(coverage(foreground_mask(far)), 0.1);
}

TEST_F(Scene, APointLightBetweenTheSpheresLightsTheirInnerSides) {
  auto client = daemon().client();
  json params = base();
  params["camera"]["projection"] = "orthographic";
  params["lights"] = {{{"type", "point"}, {"position", {0, 0, 0}}}};
  params["objects"] = {object(sphere_, {{"translate", {-2, 0, 0}}}), object(sphere_, {{"translate", {2, 0, 0}}})};
  const Image img = render_ok(client, params);
  keep(img, "scene_point_light_between.png");
  const auto mask = foreground_mask(img);
  const auto [l0, l1] = row_extent(mask, 256, 128, 0, 128);
  const auto [r0, r1] = row_extent(mask, 256, 128, 128, 256);
  ASSERT_GE(l0, 0);
  ASSERT_GE(r0, 0);
  auto lum = [&](int x) { return luminance(rgb_at(img, x, 128)); };
  const int lw = l1 - l0, rw = r1 - r0;
  // Left sphere: its right (inner) side faces the light, its left does not.
  EXPECT_GT(lum(l1 - lw / 5), lum(l0 + lw / 5) + 0.1);
  // Right sphere: the other way round.
  EXPECT_GT(lum(r0 + rw / 5), lum(r1 - rw / 5) + 0.1);
  // Both inner sides get the same light (the scene is symmetric).
  EXPECT_NEAR(lum(l1 - lw / 5), lum(r0 + rw / 5), 0.02);
}

TEST_F(Scene, MoreObjectsThanTheGpuCacheHoldsAllRender) {
  auto client = daemon().client();
  // Sixteen different models in a row (the GPU keeps eight by default): none
  // may be dropped while its scene is drawn.
  json params = base();
  params["objects"] = json::array();
  for (int i = 0; i < 16; ++i) {
    const std::string id = upload_obj_text(client, sphere_obj(8 + i, 6, 0.4), "ball.obj");
    params["objects"].push_back(object(id, {{"translate", {(i % 4) * 1.0 - 1.5, (i / 4) * 1.0 - 1.5, 0}}}));
  }
  const Image img = render_ok(client, params);
  keep(img, "scene_sixteen.png");
  // Every ball shows, apart from the others: sixteen separate blobs.
  EXPECT_EQ(blob_count(foreground_mask(img), 256, 256), 16u);
  // And the cache still serves a plain render afterwards.
  json single = base();
  single["model"] = sphere_;
  EXPECT_GT(coverage(foreground_mask(render_ok(client, single))), 0.1);
}

TEST_F(Scene, ModelAndObjectsTogetherIsAnError) {
  auto client = daemon().client();
  json params = base();
  params["model"] = sphere_;
  params["objects"] = {object(sphere_)};
  const auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  EXPECT_EQ(error_of(res).value("path", ""), "/objects") << res->body;
}

TEST_F(Scene, UnknownModelInObjectsIsNotFoundAtItsIndex) {
  auto client = daemon().client();
  json params = base();
  params["objects"] = {object(sphere_), object("0123456789abcdef0123")};
  const auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 404);
  EXPECT_EQ(error_of(res).value("path", ""), "/objects/1/model") << res->body;
}

TEST_F(Scene, BadTransformsAreRejected) {
  auto client = daemon().client();
  auto path_of = [&](json transform) {
    json params = base();
    params["objects"] = {object(sphere_, std::move(transform))};
    const auto res = post_json(client, "/render", params);
    EXPECT_TRUE(res && res->status == 400) << (res ? res->body : "no answer");
    return res ? error_of(res).value("path", "") : std::string();
  };
  EXPECT_EQ(path_of({{"spin", {0, 1, 0}}}), "/objects/0/transform/spin");
  EXPECT_EQ(path_of({{"scale", 0}}).rfind("/objects/0/transform/scale", 0), 0u);
  EXPECT_EQ(path_of({{"scale", {1, -1, 1}}}).rfind("/objects/0/transform/scale", 0), 0u);
  EXPECT_EQ(path_of({{"translate", {1, 2}}}), "/objects/0/transform/translate");
  // An empty scene, and an object without a model.
  json params = base();
  params["objects"] = json::array();
  auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  params["objects"] = {{{"transform", json::object()}}};
  res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
}

}  // namespace
}  // namespace toond::test
