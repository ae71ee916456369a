// Each lighting and effect parameter, proven by what it does to the image.
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

class Effects : public SharedDaemonTest {
 protected:
  void SetUp() override {
    auto client = daemon().client();
    sphere_ = upload_obj_text(client, sphere_obj(96, 48), "sphere.obj");
  }
  // A front view of the unit sphere, no antialiasing, no lines, no highlight:
  // every pixel is a flat band colour unless the test turns something on.
  json base() const {
    return {{"model", sphere_},
            {"width", 256},
            {"height", 256},
            {"msaa", 1},
            {"camera", {{"yaw", 0}, {"pitch", 0}}},
            {"outline", {{"enabled", false}}},
            {"specular", {{"enabled", false}}}};
  }
  std::string sphere_;
};

// Distance in pixels from (x, y) to the nearest background pixel.
double depth_inside(const std::vector<bool>& mask, int w, int h, int x, int y) {
  double best = 1e9;
  for (int yy = 0; yy < h; ++yy)
    for (int xx = 0; xx < w; ++xx)
      if (!mask[static_cast<std::size_t>(yy) * w + xx]) best = std::min(best, std::hypot(xx - x, yy - y));
  return best;
}

TEST_F(Effects, PointLightLeavesPixelsBeyondItsRadiusAtAmbient) {
  auto client = daemon().client();
  json params = base();
  params["shading"] = {{"mode", "phong"}};
  // A light just in front of the sphere, reaching 1.2 units. A sphere point
  // at angle θ from +Z is sqrt(3.25 - 3 cos θ) from the light, beyond 1.2
  // where cos θ < 0.603, i.e. (orthographic view) more than 0.80 of the
  // disk's radius from its centre.
  params["camera"]["projection"] = "orthographic";
  params["lights"] = {{{"type", "point"}, {"position", {0, 0, 1.5}}, {"radius", 1.2}}};
  const auto img = render_ok(client, params);
  params["lights"] = json::array();
  const auto ambient_only = render_ok(client, params);
  const Rgb ambient = rgb_at(ambient_only, 128, 128);
  const auto mask = foreground_mask(img);
  const int cx = 128, cy = 128;
  double radius_px = 0;
  for (int x = cx; x < 256 && mask[static_cast<std::size_t>(cy) * 256 + x]; ++x) radius_px = x - cx;
  std::size_t outside = 0, outside_at_ambient = 0;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      if (!mask[static_cast<std::size_t>(y) * 256 + x]) continue;
      const double r = std::hypot(x - cx, y - cy) / radius_px;
      if (r < 0.84 || r > 0.97) continue;  // safely beyond the radius, off the very edge
      ++outside;
      outside_at_ambient += rgb_at(img, x, y) == ambient ? 1 : 0;
    }
  }
  ASSERT_GT(outside, 100u);
  EXPECT_EQ(outside_at_ambient, outside) << "beyond the radius only ambient light remains";
  EXPECT_GT(luminance(rgb_at(img, cx, cy)), luminance(ambient) + 0.1) << "inside the radius it lights";
}

TEST_F(Effects, MaxAndSumDifferOnlyWhereLightsOverlap) {
  auto client = daemon().client();
  json params = base();
  params["lights"] = {{{"type", "directional"}, {"direction", {1, 0, -0.3}}, {"intensity", 0.6}},
                      {{"type", "directional"}, {"direction", {-1, 0, -0.3}}, {"intensity", 0.6}}};
  params["light_combine"] = "max";
  const auto max_img = render_ok(client, params);
  params["light_combine"] = "sum";
  const auto sum_img = render_ok(client, params);
  std::size_t brighter = 0, darker = 0;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const double a = luminance(rgb_at(max_img, x, y)), b = luminance(rgb_at(sum_img, x, y));
      brighter += b > a ? 1 : 0;
      darker += b < a ? 1 : 0;
    }
  }
  EXPECT_GT(brighter, 500u) << "the overlap in the middle is brighter with sum";
  EXPECT_EQ(darker, 0u) << "sum is never darker than max";
  // Where only one light reaches (the far left and right), both agree.
  EXPECT_EQ(rgb_at(max_img, 30, 128), rgb_at(sum_img, 30, 128));
}

TEST_F(Effects, SpecularIsAHardSpotThatNeverLiesInTheShadowBand) {
  auto client = daemon().client();
  json params = base();
  params["lights"] = {{{"type", "directional"}, {"direction", {-0.9, -0.3, -0.4}}}};
  params["shading"] = {{"steps", 3}};
  const auto plain = render_ok(client, params);
  params["specular"] = {{"enabled", true}, {"threshold", 0.5}, {"strength", 1}, {"color", {1, 1, 1}}};
  const auto lit = render_ok(client, params);
  // The shadow band: the darkest colour of the plain render.
  const auto hist = colour_histogram(plain, foreground_mask(plain));
  Rgb darkest = hist.begin()->first;
  for (const auto& [c, n] : hist)
    if (luminance(c) < luminance(darkest)) darkest = c;
  std::size_t highlight = 0, in_shadow = 0;
  std::set<Rgb> highlight_colours;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      if (rgb_at(plain, x, y) == rgb_at(lit, x, y)) continue;
      ++highlight;
      highlight_colours.insert(rgb_at(lit, x, y));
      in_shadow += rgb_at(plain, x, y) == darkest ? 1 : 0;
    }
  }
  EXPECT_GT(highlight, 20u);
  EXPECT_EQ(in_shadow, 0u);
  EXPECT_EQ(highlight_colours, (std::set<Rgb>{{255, 255, 255}})) << "thresholded: one hard colour";
}

TEST_F(Effects, RimBrightensARingInsideTheSilhouetteOnly) {
  auto client = daemon().client();
  json params = base();
  params["lights"] = {{{"type", "directional"}, {"direction", {0, 0, -1}}}};
  const auto plain = render_ok(client, params);
  params["rim"] = {{"enabled", true}, {"power", 4}, {"strength", 0.7}, {"threshold", 0}, {"mask", "both"}};
  const auto rimmed = render_ok(client, params);
  const auto mask = foreground_mask(plain);
  double radius_px = 0;
  for (int x = 128; x < 256 && mask[static_cast<std::size_t>(128) * 256 + x]; ++x) radius_px = x - 128;
  std::size_t changed = 0, deep_inside = 0, darker = 0, outside = 0;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      if (rgb_at(plain, x, y) == rgb_at(rimmed, x, y)) continue;
      ++changed;
      outside += mask[static_cast<std::size_t>(y) * 256 + x] ? 0 : 1;
      if (std::hypot(x - 128, y - 128) < 0.5 * radius_px) ++deep_inside;
      if (luminance(rgb_at(rimmed, x, y)) < luminance(rgb_at(plain, x, y))) ++darker;
    }
  }
  EXPECT_GT(changed, 500u);
  EXPECT_EQ(outside, 0u) << "nothing outside the silhouette";
  EXPECT_EQ(deep_inside, 0u) << "the middle of the disk keeps its colour";
  EXPECT_EQ(darker, 0u) << "a white rim only brightens";
  // Not washed out: even at the rim the colour stays below pure white.
  EXPECT_LT(luminance(rgb_at(rimmed, 128 + static_cast<int>(radius_px) - 2, 128)), 0.99);
}

TEST_F(Effects, RimMaskKeepsToTheChosenSide) {
  auto client = daemon().client();
  json params = base();
  params["lights"] = {{{"type", "directional"}, {"direction", {-1, 0, 0}}}};  // lights the right half
  const auto plain = render_ok(client, params);
  for (const char* side : {"lit", "shadow"}) {
    params["rim"] = {{"enabled", true}, {"strength", 0.7}, {"threshold", 0}, {"mask", side}};
    const auto rimmed = render_ok(client, params);
    std::size_t left = 0, right = 0;
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x)
        if (rgb_at(plain, x, y) != rgb_at(rimmed, x, y)) (x < 128 ? left : right) += 1;
    if (std::string(side) == "lit") {
      EXPECT_GT(right, 100u);
      EXPECT_EQ(left, 0u);
    } else {
      EXPECT_GT(left, 100u);
      EXPECT_EQ(right, 0u);
    }
  }
}

// Autocorrelation of the ink mask along x: its strongest lag is the period.
int dominant_period(const Image& img, int y0, int y1, int x0, int x1, int min_lag, int max_lag) {
  int best_lag = 0;
  double best = -1;
  for (int lag = min_lag; lag <= max_lag; ++lag) {
    double sum = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x + lag < x1; ++x) sum += luminance(rgb_at(img, x, y)) * luminance(rgb_at(img, x + lag, y));
    sum /= (x1 - x0 - lag);
    if (sum > best) {
      best = sum;
      best_lag = lag;
    }
  }
  return best_lag;
}

TEST_F(Effects, HalftoneDotsRepeatWithTheCellSize) {
  auto client = daemon().client();
  json params = base();
  params["shading"] = {{"mode", "phong"}};
  params["lights"] = {{{"type", "directional"}, {"direction", {-1, 0, -0.2}}}};
  for (int cell : {6, 10}) {
    params["halftone"] = {{"enabled", true}, {"style", "dots"},  {"cell", cell},
                          {"angle", 0},      {"ink", {0, 0, 0}}, {"ink_mix", 1}};
    const auto img = render_ok(client, params);
    // The dots grow toward the shadow side; measure in the mid tones.
    EXPECT_EQ(dominant_period(img, 100, 156, 60, 150, 3, 16), cell) << "cell " << cell;
    // Two tones only (plus the background): lit colour and ink.
    const auto hist = colour_histogram(img, foreground_mask(img));
    EXPECT_LE(hist.size(), 12u) << "few colours: ink, paper and the highlight-free lit tone";
  }
}

TEST_F(Effects, CheckerHalftoneOnlyTouchesTheMidBands) {
  auto client = daemon().client();
  json params = base();
  params["lights"] = {{{"type", "directional"}, {"direction", {-1, 0, -0.4}}}};
  // Hard bands, so "the brightest band" is one colour.
  params["shading"] = {{"steps", 3}, {"band_aa", false}};
  const auto plain = render_ok(client, params);
  params["halftone"] = {{"enabled", true}, {"style", "checker"}, {"cell", 4}};
  const auto checked = render_ok(client, params);
  // The brightest band is untouched.
  Rgb brightest{0, 0, 0};
  for (const auto& [c, n] : colour_histogram(plain, foreground_mask(plain)))
    if (luminance(c) > luminance(brightest)) brightest = c;
  std::size_t changed = 0, changed_in_top_band = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x)
      if (rgb_at(plain, x, y) != rgb_at(checked, x, y)) {
        ++changed;
        changed_in_top_band += rgb_at(plain, x, y) == brightest ? 1 : 0;
      }
  EXPECT_GT(changed, 200u);
  EXPECT_EQ(changed_in_top_band, 0u);
}

TEST_F(Effects, ContourDrawsEvenLinesInsideTheSilhouette) {
  auto client = daemon().client();
  json params = base();
  params["lights"] = {{{"type", "directional"}, {"direction", {0, 0, -1}}}};
  const auto plain = render_ok(client, params);
  params["contour"] = {{"enabled", true}, {"style", "even"}, {"width", 3}, {"color", {0, 0, 0}}};
  const auto lined = render_ok(client, params);
  const auto mask = foreground_mask(plain);
  std::size_t changed = 0, too_deep = 0;
  for (int y = 0; y < 256; y += 2) {
    for (int x = 0; x < 256; x += 2) {
      if (rgb_at(plain, x, y) == rgb_at(lined, x, y)) continue;
      ++changed;
      EXPECT_EQ(rgb_at(lined, x, y), (Rgb{0, 0, 0}));
      if (depth_inside(mask, 256, 256, x, y) > 3 + 1.5) ++too_deep;
    }
  }
  EXPECT_GT(changed, 50u);
  EXPECT_EQ(too_deep, 0u) << "the even line is about `width` pixels wide";
}

// sRGB byte of a linear value, for expected colours.
int srgb_byte(double linear) {
  const double c = linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(c * 255));
}

// Front light on an orthographic unit sphere: N·L at a pixel r (in disk
// radii) from the centre is sqrt(1 - r²), so every ramp edge has a radius.
class RampEffects : public Effects {
 protected:
  json front_lit() const {
    json params = base();
    params["camera"]["projection"] = "orthographic";
    params["ambient"] = 0;
    params["lights"] = {{{"type", "directional"}, {"direction", {0, 0, -1}}}};
    return params;
  }
  // Colour at r disk radii right of the centre.
  static Rgb at_radius(const Image& img, double r) {
    const auto mask = foreground_mask(img);
    int edge = img.width / 2;
    while (edge + 1 < img.width && mask[static_cast<std::size_t>(img.height / 2) * img.width + edge + 1]) ++edge;
    const double radius_px = edge - img.width / 2 + 0.5;
    return rgb_at(img, img.width / 2 + static_cast<int>(r * radius_px), img.height / 2);
  }
};

TEST_F(RampEffects, TwoTonePaletteHasTwoColoursSplitAtTheThreshold) {
  auto client = daemon().client();
  json params = front_lit();
  params["shading"] = {{"two_tone", {{"enabled", true}, {"threshold", 0.25}, {"shadow_factor", 0.25}}},
                       {"band_aa", false}};
  const auto img = render_ok(client, params);
  EXPECT_EQ(colour_histogram(img, foreground_mask(img)).size(), 2u);
  // Kd 0.8: lit 0.8, shadow a quarter of it, 0.2 (linear).
  EXPECT_EQ(at_radius(img, 0.5).r, srgb_byte(0.8));
  EXPECT_EQ(at_radius(img, 0.99).r, srgb_byte(0.2));
  // N·L = 0.25 at r = 0.968.
  EXPECT_EQ(at_radius(img, 0.94).r, srgb_byte(0.8));
}

TEST_F(RampEffects, RampStopsSetLevelsAndColoursAtTheirNdotL) {
  auto client = daemon().client();
  json params = front_lit();
  // The first stop starts at -1: silhouette samples whose interpolated
  // normal tips just past 90° (N·L < 0) would otherwise fall below it, where
  // the ramp documents no light.
  params["shading"] = {{"ramp", json::array({json{{"at", -1}, {"value", 0.25}}, json{{"at", 0.5}, {"color", {1, 0, 0}}},
                                             json{{"at", 0.9}, {"value", 1}}})}};
  const auto img = render_ok(client, params);
  EXPECT_EQ(colour_histogram(img, foreground_mask(img)).size(), 3u);
  // N·L >= 0.9 inside r = 0.436; >= 0.5 inside r = 0.866.
  const auto lit = static_cast<std::uint8_t>(srgb_byte(0.8));
  EXPECT_EQ(at_radius(img, 0.2), (Rgb{lit, lit, lit}));
  EXPECT_EQ(at_radius(img, 0.65), (Rgb{lit, 0, 0})) << "the red stop tints";
  EXPECT_EQ(at_radius(img, 0.95).r, srgb_byte(0.2));
}

// A per-material shade colour replaces material × ambient in the darkest
// band and leaves the fully lit band alone; other materials keep theirs.
TEST_F(RampEffects, ShadeColourPerMaterial) {
  auto client = daemon().client();
  json params = front_lit();
  params["ambient"] = 0.3;
  params["shading"] = {{"steps", 2}};
  params["lights"] = {{{"type", "directional"}, {"direction", {-1, 0, 0}}}};  // lights the right half
  const auto plain = render_ok(client, params);
  params["shading"]["shade_colors"] = {{"default", {0, 0, 1}}};
  const auto blue = render_ok(client, params);
  const int cx = 128, cy = 128;
  EXPECT_EQ(rgb_at(blue, cx - 60, cy), (Rgb{0, 0, 255})) << "the unlit left half takes the shade colour";
  EXPECT_EQ(rgb_at(blue, cx + 60, cy), rgb_at(plain, cx + 60, cy)) << "the top band is unchanged";
  params["shading"]["shade_colors"] = {{"no_such_material", {0, 0, 1}}};
  const auto other = render_ok(client, params);
  EXPECT_EQ(other.rgba, plain.rgba) << "a colour for another material changes nothing";
}

TEST_F(Effects, OutlineColourFromTheMaterialDarkened) {
  auto client = daemon().client();
  json params = base();
  params["outline"] = {{"enabled", true}, {"width", 4}, {"color_mode", "material"}, {"darken", 0.5}};
  const auto img = render_ok(client, params);
  // Kd 0.8 darkened by half is 0.4 linear: every outline pixel has it.
  const auto line = static_cast<std::uint8_t>(srgb_byte(0.4));
  const Rgb expected{line, line, line};
  params["outline"]["enabled"] = false;
  const auto bare = render_ok(client, params);
  std::size_t ring = 0, wrong = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x)
      if (rgb_at(bare, x, y) != rgb_at(img, x, y)) {
        ++ring;
        wrong += rgb_at(img, x, y) != expected ? 1 : 0;
      }
  EXPECT_GT(ring, 500u);
  EXPECT_EQ(wrong, 0u);
}

// The sphere lit from straight ahead: nothing it faces is behind anything,
// so shadows on must not change one pixel (no acne, no stray shadow).
TEST_F(Effects, NoShadowAcneOnAConvexModelLitFromTheFront) {
  auto client = daemon().client();
  json params = base();
  params["lights"] = {{{"type", "directional"}, {"direction", {0, 0, -1}}}};
  params["shading"] = {{"steps", 4}};
  const auto without = render_ok(client, params);
  for (int map_size : {512, 2048}) {
    params["shadows"] = {{"enabled", true}, {"map_size", map_size}};
    const auto with = render_ok(client, params);
    std::size_t differ = 0;
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x) differ += rgb_at(with, x, y) != rgb_at(without, x, y) ? 1 : 0;
    EXPECT_EQ(differ, 0u) << "map " << map_size;
  }
}

class FloorAndShadows : public Effects {
 protected:
  json scene() const {
    json params = base();
    params["camera"] = {{"yaw", 20}, {"pitch", 35}};
    params["lights"] = {{{"type", "directional"}, {"direction", {0.3, -1, -0.2}}}};
    params["floor"] = {{"enabled", true}, {"size", 1.6}, {"color", {0.9, 0.9, 0.85}}};
    return params;
  }
};

TEST_F(FloorAndShadows, FloorIsDarkerUnderTheModelWithShadowsOn) {
  auto client = daemon().client();
  json params = scene();
  const auto lit = render_ok(client, params);
  params["shadows"] = {{"enabled", true}};
  auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("X-Toond-Passes"), "shadow,main,floor,readback");
  const auto shadowed = image::decode_png(res->body);
  std::size_t darker = 0, brighter = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const double a = luminance(rgb_at(lit, x, y)), b = luminance(rgb_at(shadowed, x, y));
      darker += b < a ? 1 : 0;
      brighter += b > a ? 1 : 0;
    }
  EXPECT_GT(darker, 1000u) << "a shadow on the floor";
  EXPECT_EQ(brighter, 0u);
}

TEST_F(FloorAndShadows, FloorGetsNoOutline) {
  auto client = daemon().client();
  json params = scene();
  params["floor"]["enabled"] = false;
  const auto sphere_only = render_ok(client, params);
  params["floor"]["enabled"] = true;
  const auto bare = render_ok(client, params);
  params["outline"] = {{"enabled", true}, {"width", 3}, {"color", {1, 0, 0}}};
  const auto outlined = render_ok(client, params);
  // Every outline pixel hugs the sphere's silhouette, none the floor's edge.
  const auto sphere_mask = foreground_mask(sphere_only);
  std::size_t ring = 0, far_from_sphere = 0;
  for (int y = 0; y < 256; y += 1)
    for (int x = 0; x < 256; x += 1) {
      if (rgb_at(bare, x, y) == rgb_at(outlined, x, y)) continue;
      ++ring;
      bool near = false;
      for (int dy = -5; dy <= 5 && !near; ++dy)
        for (int dx = -5; dx <= 5 && !near; ++dx) {
          const int xx = x + dx, yy = y + dy;
          near = xx >= 0 && yy >= 0 && xx < 256 && yy < 256 && sphere_mask[static_cast<std::size_t>(yy) * 256 + xx];
        }
      far_from_sphere += near ? 0 : 1;
    }
  EXPECT_GT(ring, 200u);
  EXPECT_EQ(far_from_sphere, 0u);
}

// Back-face wireframe lines show past the silhouette `width` pixels wide.
TEST_F(Effects, WireframeOutlineHasTheRequestedWidth) {
  auto client = daemon().client();
  json params = base();
  const auto bare = render_ok(client, params);
  for (double width : {2.0, 5.0}) {
    params["outline"] = {{"enabled", true}, {"method", "wireframe"}, {"width", width}, {"color", {0, 0, 0}}};
    EXPECT_NEAR(outline_width_px(bare, render_ok(client, params)), width, 1.0) << "width " << width;
  }
}

// The edge pass finds creases the hull cannot: a cube's inner edges.
TEST_F(Effects, EdgePassDrawsCreasesInsideTheSilhouette) {
  auto client = daemon().client();
  const std::string cube = upload_obj_text(client, cube_obj(), "cube.obj");
  json params = base();
  params["model"] = cube;
  params["camera"] = {{"yaw", 30}, {"pitch", 25}};
  const auto bare = render_ok(client, params);
  const auto inside = foreground_mask(bare);
  // Pixels inside the silhouette the lines changed, each darkened toward
  // the black line colour (a line's sides are blended by their coverage);
  // returns how many are fully black.
  auto dark_inside = [&](const json& outline) {
    params["outline"] = outline;
    const auto img = render_ok(client, params);
    std::size_t black = 0;
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x)
        if (inside[static_cast<std::size_t>(y) * 256 + x] && rgb_at(img, x, y) != rgb_at(bare, x, y)) {
          const Rgb lined = rgb_at(img, x, y), plain = rgb_at(bare, x, y);
          EXPECT_TRUE(lined.r <= plain.r && lined.g <= plain.g && lined.b <= plain.b)
              << "at " << x << "," << y << " a line made a pixel lighter";
          black += lined == (Rgb{0, 0, 0}) ? 1 : 0;
        }
    return black;
  };
  EXPECT_EQ(dark_inside({{"method", "hull"}, {"width", 3}, {"color", {0, 0, 0}}, {"creases", "never"}}), 0u);
  // The default outline on this hard-edged cube brings its crease lines:
  // the three inner edges, as the edge method draws them.
  const std::size_t default_creases = dark_inside({{"width", 3}, {"color", {0, 0, 0}}});
  EXPECT_GT(default_creases, 150u);
  // Three inner edges of about 100 pixels each, a few pixels wide.
  const std::size_t creased = dark_inside({{"method", "edges"}, {"width", 3}, {"color", {0, 0, 0}}});
  EXPECT_GT(creased, 300u);
  // A crease angle above the cube's 90° finds no crease: what is left inside
  // is only the silhouette line's inner half. The creases add three lines
  // of about 100 pixels, each with two or more fully black pixels across.
  const std::size_t uncreased =
      dark_inside({{"method", "edges"}, {"width", 3}, {"color", {0, 0, 0}}, {"crease_angle", 120}});
  EXPECT_GT(creased, uncreased + 450);
}

TEST_F(Effects, OutlineMethodsCombine) {
  auto client = daemon().client();
  json params = base();
  params["outline"] = {{"enabled", true}, {"method", {"hull", "wireframe", "edges"}}, {"width", 2}};
  auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("X-Toond-Passes"), "main,hull_outline,wireframe,edge_prepass,edges,readback");
  params["outline"]["method"] = {"hull", "hull"};
  res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400) << "a method named twice";
  EXPECT_EQ(error_of(res)["path"], "/outline/method");
}

// In world units the hull is a fixed thickness in model space: twice as far
// away, half as many pixels.
TEST_F(Effects, OutlineInWorldUnitsThinsWithDistance) {
  auto client = daemon().client();
  auto width_at = [&](double distance) {
    json params = base();
    params["camera"]["distance"] = distance;
    params["camera"]["fov"] = 30;
    const auto bare = render_ok(client, params);
    params["outline"] = {{"enabled", true}, {"units", "world"}, {"width", 0.08}};
    return outline_width_px(bare, render_ok(client, params));
  };
  const double near = width_at(4.0), far = width_at(8.0);
  EXPECT_GT(near, 4.0);
  EXPECT_NEAR(near / far, 2.0, 0.4) << near << " px at 4, " << far << " px at 8";
}

TEST_F(Effects, EveryPresetLooksDifferent) {
  auto client = daemon().client();
  auto res = client.Get("/presets");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  const json presets = json::parse(res->body);
  std::set<std::vector<std::uint8_t>> seen;
  for (const auto& [name, preset] : presets.items()) {
    EXPECT_FALSE(preset["description"].get<std::string>().empty()) << name;
    json params = {{"preset", name}, {"width", 128}, {"height", 128}};
    const auto img = render_ok(client, params);
    EXPECT_TRUE(seen.insert(img.rgba).second) << name << " renders the same as another preset";
  }
  EXPECT_GE(seen.size(), 7u);
}

TEST_F(Effects, ExplicitFieldsOverrideThePreset) {
  auto client = daemon().client();
  auto res = post_json(client, "/render",
                       {{"preset", "bw_comic"}, {"outline", {{"width", 0}}}, {"width", 64}, {"height", 64}});
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("X-Toond-Passes").find("hull_outline"), std::string::npos);
  auto with_outline = post_json(client, "/render", {{"preset", "bw_comic"}, {"width", 64}, {"height", 64}});
  ASSERT_TRUE(with_outline);
  EXPECT_NE(with_outline->get_header_value("X-Toond-Passes").find("hull_outline"), std::string::npos);
}

TEST_F(Effects, UnknownPresetIsRejected) {
  auto client = daemon().client();
  auto res = post_json(client, "/render", {{"preset", "vaporwave"}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  EXPECT_EQ(error_of(res)["path"], "/preset");
}

}  // namespace
}  // namespace toond::test
