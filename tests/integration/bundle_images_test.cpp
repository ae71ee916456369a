// Request parameters that name image files of the model's bundle: a ramp
// drawn as an image (shading.ramp_image) and a floor texture (floor.texture).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "support/image_checks.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

// A grey image `greys.size()` texels wide and one high, as PNG bytes.
std::string grey_row_png(const std::vector<std::uint8_t>& greys) {
  image::Image img;
  img.width = static_cast<int>(greys.size());
  img.height = 1;
  for (std::uint8_t g : greys) img.rgba.insert(img.rgba.end(), {g, g, g, 255});
  return image::encode_png(img);
}

class BundleImages : public SharedDaemonTest {
 protected:
  void SetUp() override {
    auto client = daemon().client();
    // A sphere whose bundle carries a 4-texel ramp (3 shades), a gradient
    // that is no cel ramp, and a file that is no image.
    std::vector<std::uint8_t> gradient;
    for (int i = 0; i < 40; ++i) gradient.push_back(static_cast<std::uint8_t>(i * 6));
    httplib::MultipartFormDataItems items = {
        {"file", sphere_obj(96, 48), "sphere.obj", "text/plain"},
        {"file", grey_row_png({40, 40, 130, 230}), "ramps/three.png", "image/png"},
        {"file", grey_row_png(gradient), "ramps/gradient.png", "image/png"},
        {"file", "not an image", "notes/readme.png", "image/png"},
    };
    auto res = client.Post("/models", items);
    ASSERT_TRUE(res);
    ASSERT_TRUE(res->status == 200 || res->status == 201) << res->body;
    sphere_ = json::parse(res->body)["id"];
  }
  // Front-lit orthographic sphere, nothing but the diffuse bands.
  json base() const {
    return {{"model", sphere_},
            {"width", 200},
            {"height", 200},
            {"camera", {{"projection", "orthographic"}}},
            {"shading", {{"base", "white"}}},
            {"outline", {{"enabled", false}}},
            {"specular", {{"enabled", false}}}};
  }
  std::string sphere_;
};

TEST_F(BundleImages, RampImageShadesExactlyLikeTheSameRampAsStops) {
  auto client = daemon().client();
  json from_image = base();
  from_image["shading"]["ramp_image"] = "ramps/three.png";
  const auto a = render_ok(client, from_image);

  // Texel i of 4 covers N·L in [i/4, (i+1)/4); texel 0 also everything below.
  auto grey = [](int g) { return json::array({g / 255.0, g / 255.0, g / 255.0}); };
  json from_stops = base();
  from_stops["shading"]["ramp"] = {
      {{"at", -1}, {"color", grey(40)}}, {{"at", 0.5}, {"color", grey(130)}}, {{"at", 0.75}, {"color", grey(230)}}};
  const auto b = render_ok(client, from_stops);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  EXPECT_EQ(a.rgba, b.rgba);

  // And it is not the default three bands.
  const auto bands = render_ok(client, base());
  EXPECT_NE(a.rgba, bands.rgba);
  // Along the disk's radius R, N·L = sqrt(1 - (r/R)²): the centre and
  // r = 0.5 R (N·L 0.87) share the top texel; r = 0.95 R (N·L 0.31) is in
  // the shadow band, texel 0 or 1 (both 40).
  const auto mask = foreground_mask(a);
  int radius = 0;
  while (100 + radius + 1 < 200 && mask[100 * 200 + 100 + radius + 1]) ++radius;
  ASSERT_GT(radius, 50);
  const Rgb centre = rgb_at(a, 100, 100);
  EXPECT_EQ(rgb_at(a, 100 + radius / 2, 100), centre);
  const Rgb shadow = rgb_at(a, 100 + radius * 95 / 100, 100);
  EXPECT_LT(luminance(shadow) + 0.3, luminance(centre));
}

TEST_F(BundleImages, TheDemoCarriesASharpLightingMap) {
  auto client = daemon().client();
  json params = {{"width", 160}, {"height", 160}, {"shading", {{"ramp_image", "ramps/sharp.png"}}}};
  const auto sharp = render_ok(client, params);
  params["shading"].erase("ramp_image");
  const auto bands = render_ok(client, params);
  EXPECT_NE(sharp.rgba, bands.rgba);
}

TEST_F(BundleImages, RampImageErrorsNameTheParameter) {
  auto client = daemon().client();
  const struct {
    const char* path;
    const char* code;
    const char* says;
  } cases[] = {
      {"ramps/missing.png", "missing_file", "no file"},
      {"../ramps/three.png", "missing_file", "no file"},  // never leaves the bundle
      {"/etc/passwd", "missing_file", "no file"},
      {"notes/readme.png", "bad_image", "not a readable image"},
      {"ramps/gradient.png", "bad_image", "40 runs"},
  };
  for (const auto& c : cases) {
    json params = base();
    params["shading"]["ramp_image"] = c.path;
    auto res = post_json(client, "/render", params);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 422) << c.path;
    const json error = error_of(res);
    EXPECT_EQ(error["code"], c.code) << c.path;
    EXPECT_EQ(error["path"], "/shading/ramp_image") << c.path;
    EXPECT_NE(error["message"].get<std::string>().find(c.says), std::string::npos) << error.dump();
  }
}

// Looking steeply down at the demo on a floor six bounding radii wide: the
// floor fills the frame and the bottom rows see nothing else.
class FloorTexture : public SharedDaemonTest {
 protected:
  static json scene() {
    // Zoomed out so the bottom rows show floor only.
    return {{"width", 160},
            {"height", 160},
            {"camera", {{"pitch", 75}, {"zoom", 0.6}}},
            {"outline", {{"enabled", false}}},
            {"floor", {{"enabled", true}, {"color", {1, 1, 1}}, {"size", 6}}}};
  }
  // Distinct colours among the bottom rows' pixels.
  static std::size_t floor_colours(const image::Image& img) {
    std::set<Rgb> colours;
    for (int y = img.height - 12; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) colours.insert(rgb_at(img, x, y));
    return colours.size();
  }
};

TEST_F(FloorTexture, TilesTheBundlesImageOverTheFloor) {
  auto client = daemon().client();
  json params = scene();
  const auto plain = render_ok(client, params);
  EXPECT_EQ(floor_colours(plain), 1u) << "a plain floor is one colour";
  params["floor"]["texture"] = "textures/floor.png";
  const auto tiled = render_ok(client, params);
  EXPECT_GE(floor_colours(tiled), 2u);
  // Light and dark tiles both show, far apart in brightness.
  double lo = 1, hi = 0;
  for (int x = 0; x < tiled.width; ++x) {
    const double l = luminance(rgb_at(tiled, x, tiled.height - 3));
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  EXPECT_GT(hi - lo, 0.15);
  // More repeats, smaller tiles: the bottom row changes tone more often.
  auto changes = [](const image::Image& img) {
    int n = 0;
    for (int x = 1; x < img.width; ++x)
      n += std::abs(luminance(rgb_at(img, x, img.height - 3)) - luminance(rgb_at(img, x - 1, img.height - 3))) > 0.08;
    return n;
  };
  params["floor"]["texture_repeat"] = 16;
  EXPECT_GT(changes(render_ok(client, params)), changes(tiled));
}

TEST_F(FloorTexture, MissingFloorTextureIs422) {
  auto client = daemon().client();
  json params = scene();
  params["floor"]["texture"] = "textures/nope.png";
  auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422);
  EXPECT_EQ(error_of(res)["path"], "/floor/texture");
}

}  // namespace
}  // namespace toond::test
