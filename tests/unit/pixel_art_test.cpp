// Pixel art and animation for sprite sheets, without GL: the shared palette
// (median cut), nearest-colour mapping with and without ordered dithering,
// whole-factor enlargement, the lossless animated WebP read back by
// libwebp's own decoder, and the request checks around them.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "image/block_upscale.h"
#include "image/palette_quantise.h"
#include "image/webp_animation.h"
#include "limit_error.h"
#include "param_schema.h"
#include "pipeline/budget.h"
#include "pipeline/frames.h"
#include "pipeline/render_params_wire.h"
#include "pipeline/sheet_checks.h"
#include "render/plan/pixel_art_frame.h"
#include "request_error.h"
#include "support/webp_frames.h"

namespace toond {
namespace {

using image::Image;
using image::Rgb8;
using nlohmann::json;

Image blank(int width, int height) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
  return img;
}

void set(Image& img, int x, int y, Rgb8 c, std::uint8_t a = 255) {
  std::uint8_t* p = img.pixel(x, y);
  p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = a;
}

Rgb8 rgb_at(const Image& img, int x, int y) {
  const std::uint8_t* p = img.pixel(x, y);
  return {p[0], p[1], p[2]};
}

// Seeded noise: every colour different, the worst case for a palette.
Image noise(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  Image img = blank(width, height);
  for (auto& byte : img.rgba) byte = static_cast<std::uint8_t>(random());
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  return img;
}

std::set<std::uint32_t> visible_colours(const Image& img) {
  std::set<std::uint32_t> colours;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (p[3] != 0) colours.insert((std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | p[2]);
    }
  }
  return colours;
}

render::RenderParams params_of(const json& request) {
  return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(request));
}

// The budget as the pipeline checks it: on the sheet laid out once.
void check_budget(const render::RenderParams& params, const pipeline::RenderLimits& limits) {
  pipeline::check_render_budget(params, pipeline::layout_of(params), limits);
}

TEST(MedianCut, FewColoursAreKeptExactly) {
  Image img = blank(4, 1);
  set(img, 0, 0, {10, 20, 30});
  set(img, 1, 0, {200, 0, 0});
  set(img, 2, 0, {10, 20, 30});
  const Image* images[] = {&img};
  const std::vector<Rgb8> palette = image::median_cut_palette(images, 4);
  EXPECT_EQ(palette, (std::vector<Rgb8>{{10, 20, 30}, {200, 0, 0}})) << "the transparent pixel takes no entry";
}

TEST(MedianCut, AtMostNColoursWhateverTheOrderOfTheImages) {
  const Image a = noise(32, 32, 1), b = noise(32, 32, 2);
  const Image* ab[] = {&a, &b};
  const Image* ba[] = {&b, &a};
  for (int n : {2, 7, 16, 256}) {
    const std::vector<Rgb8> palette = image::median_cut_palette(ab, n);
    EXPECT_LE(palette.size(), static_cast<std::size_t>(n));
    EXPECT_GE(palette.size(), static_cast<std::size_t>(n) * 3 / 4) << "noise is splittable nearly to n boxes";
    EXPECT_EQ(palette, image::median_cut_palette(ba, n)) << "n = " << n;
  }
}

// Without dithering each visible pixel becomes exactly the entry nearest
// its own colour; alpha and transparent pixels are left alone.
TEST(Quantise, WithoutDitherEveryPixelIsItsNearestEntry) {
  const Image original = noise(48, 40, 3);
  Image img = original;
  set(img, 5, 5, {1, 2, 3}, 0);
  set(img, 6, 5, {250, 2, 3}, 128);
  const Image before = img;
  const std::vector<Rgb8> palette = {{0, 0, 0}, {255, 255, 255}, {255, 0, 0}, {0, 128, 255}, {90, 200, 40}};
  image::quantise_to_palette(img, palette, false);
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* was = before.pixel(x, y);
      const std::uint8_t* now = img.pixel(x, y);
      ASSERT_EQ(now[3], was[3]) << "alpha kept at " << x << "," << y;
      if (was[3] == 0) {
        EXPECT_TRUE(std::equal(was, was + 4, now)) << "a transparent pixel stays as it was";
        continue;
      }
      const Rgb8 nearest = palette[image::nearest_entry(palette, rgb_at(before, x, y))];
      ASSERT_EQ(rgb_at(img, x, y), nearest) << x << "," << y;
      // And really nearest: no entry is closer.
      auto distance = [&](Rgb8 c) {
        const int dr = c.r - was[0], dg = c.g - was[1], db = c.b - was[2];
        return dr * dr + dg * dg + db * db;
      };
      for (const Rgb8& other : palette) ASSERT_LE(distance(nearest), distance(other));
    }
  }
}

// A grey ramp onto black and white: plain quantising gives one edge in the
// middle; ordered dithering mixes the two in proportion to the grey.
TEST(Quantise, OrderedDitherMixesNeighbouringEntriesOnlyWhenAsked) {
  Image ramp = blank(256, 8);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 256; ++x)
      set(ramp, x, y, {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(x)});
  }
  const std::vector<Rgb8> palette = {{0, 0, 0}, {255, 255, 255}};
  Image plain = ramp;
  image::quantise_to_palette(plain, palette, false);
  for (int x = 0; x < 256; ++x) EXPECT_EQ(rgb_at(plain, x, 3).r, x < 128 ? 0 : 255) << x;

  Image dithered = ramp;
  image::quantise_to_palette(dithered, palette, true);
  // Quarter, half and three-quarter grey: about that share of white in a
  // 4×4 window (the Bayer cell), and in between nothing but black and white.
  for (int x0 : {62, 126, 190}) {
    int white = 0;
    for (int y = 0; y < 4; ++y) {
      for (int x = x0; x < x0 + 4; ++x) white += rgb_at(dithered, x, y).r == 255;
    }
    EXPECT_NEAR(white / 16.0, (x0 + 1.5) / 255.0, 2.0 / 16) << "around grey " << x0;
  }
  EXPECT_EQ(visible_colours(dithered).size(), 2u);
  EXPECT_EQ(rgb_at(dithered, 0, 0).r, 0) << "black stays black";
  EXPECT_EQ(rgb_at(dithered, 255, 0).r, 255) << "white stays white";
}

TEST(BlockUpscale, EveryPixelBecomesAScaleByScaleBlockInPlace) {
  const Image small = noise(5, 3, 4);
  Image big = blank(30, 20);
  image::blit_upscaled(small, 4, big, 6, 7);
  for (int y = 0; y < big.height; ++y) {
    for (int x = 0; x < big.width; ++x) {
      const bool inside = x >= 6 && x < 6 + 20 && y >= 7 && y < 7 + 12;
      const std::uint8_t* p = big.pixel(x, y);
      if (!inside) {
        ASSERT_EQ(p[3], 0) << "outside the block at " << x << "," << y;
        continue;
      }
      const std::uint8_t* s = small.pixel((x - 6) / 4, (y - 7) / 4);
      ASSERT_TRUE(std::equal(s, s + 4, p)) << x << "," << y;
    }
  }
}

// Lossless and `exact`: every frame decodes to the bytes given. libwebp
// may rewrite the RGB of fully transparent pixels unless told not to, so
// alpha is compared everywhere and RGB only where alpha > 0; that RGB under
// alpha 0 survives too (WebPConfig::exact) is checked on its own.
TEST(WebpAnimation, DecodesToEveryFrameExactlyLoopingForever) {
  std::vector<Image> frames;
  for (unsigned i = 0; i < 5; ++i) {
    Image frame = noise(24, 16, 10 + i);
    for (int x = 0; x < 24; ++x) set(frame, x, 0, {static_cast<std::uint8_t>(40 * i), 7, 9}, 0);  // transparent row
    for (int x = 0; x < 24; ++x) set(frame, x, 1, {1, 2, 3}, static_cast<std::uint8_t>(x * 10));  // translucent
    frames.push_back(frame);
  }
  image::WebpAnimationOptions options;
  options.frame_ms = 120;
  const std::string bytes = image::encode_webp_animation(frames, options);
  ASSERT_EQ(bytes.substr(0, 4), "RIFF");
  ASSERT_EQ(bytes.substr(8, 4), "WEBP");
  const test::WebpFrames decoded = test::decode_webp_frames(bytes);
  EXPECT_EQ(decoded.loop_count, 0) << "loops forever";
  ASSERT_EQ(decoded.frames.size(), frames.size());
  bool rgb_under_transparent_kept = true;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(decoded.end_ms[i], static_cast<int>(i + 1) * 120);
    ASSERT_EQ(decoded.frames[i].width, 24);
    ASSERT_EQ(decoded.frames[i].height, 16);
    for (std::size_t p = 0; p < frames[i].rgba.size(); p += 4) {
      const std::uint8_t* want = &frames[i].rgba[p];
      const std::uint8_t* got = &decoded.frames[i].rgba[p];
      ASSERT_EQ(got[3], want[3]) << "frame " << i << " byte " << p;
      if (want[3] > 0) {
        ASSERT_TRUE(std::equal(want, want + 3, got)) << "frame " << i << " pixel " << p / 4;
      } else {
        rgb_under_transparent_kept = rgb_under_transparent_kept && std::equal(want, want + 3, got);
      }
    }
  }
  EXPECT_TRUE(rgb_under_transparent_kept) << "WebPConfig::exact keeps RGB under alpha 0";
}

TEST(WebpAnimation, IdenticalNeighboursMergeKeepingTheTiming) {
  const Image a = noise(16, 16, 20), b = noise(16, 16, 21);
  const std::vector<Image> frames = {a, a, b};
  const test::WebpFrames decoded = test::decode_webp_frames(image::encode_webp_animation(frames));
  ASSERT_EQ(decoded.frames.size(), 2u) << "libwebp shows the repeated frame longer instead";
  EXPECT_EQ(decoded.end_ms, (std::vector<int>{200, 300}));
  EXPECT_THROW(image::encode_webp_animation(std::vector<Image>{}), std::invalid_argument);
  EXPECT_THROW(image::encode_webp_animation(std::vector<Image>{a, noise(8, 8, 1)}), std::invalid_argument);
}

TEST(PixelArtParams, WireFieldsParseAndDrawSmallWithoutAntialiasing) {
  const render::RenderParams p = params_of(
      {{"width", 64},
       {"height", 32},
       {"msaa", 8},
       {"supersample", 2},
       {"sheet",
        {{"frames", 4}, {"animate", true}, {"pixel_art", {{"scale", 8}, {"palette", {"#ff8000", "#0A0b0C"}}}}}}});
  ASSERT_TRUE(p.sheet && p.sheet->pixel_art);
  EXPECT_EQ(p.sheet->pixel_art->scale, 8);
  EXPECT_EQ(p.sheet->pixel_art->colors, 16) << "the default";
  EXPECT_FALSE(p.sheet->pixel_art->dither) << "no dithering unless asked";
  EXPECT_EQ(p.sheet->pixel_art->palette,
            (std::vector<std::array<std::uint8_t, 3>>{{0xff, 0x80, 0x00}, {0x0a, 0x0b, 0x0c}}));
  EXPECT_TRUE(p.sheet->animate);
  EXPECT_EQ(p.sheet->frame_ms, 100) << "the default";
  EXPECT_FALSE(params_of({{"sheet", {{"frames", 2}}}}).sheet->pixel_art) << "no pixel art unless asked";
  EXPECT_FALSE(params_of({{"sheet", {{"frames", 2}}}}).sheet->animate);

  const render::RenderParams drawn = render::pixel_art_frame_params(p, *p.sheet->pixel_art);
  EXPECT_EQ(drawn.width, 8);
  EXPECT_EQ(drawn.height, 4);
  EXPECT_EQ(drawn.msaa, 1);
  EXPECT_EQ(drawn.supersample, 1);
  EXPECT_FALSE(drawn.band_aa);
}

TEST(PixelArtParams, SpriteLinesByDefaultAndTheRequestsOwnWhenAsked) {
  const json lines = {{"outline", {{"width", 3.5}, {"units", "world"}}}, {"contour", {{"enabled", true}}}};
  json request = lines;
  request["sheet"] = {{"frames", 2}, {"pixel_art", {{"scale", 2}}}};
  const render::RenderParams sprite = params_of(request);
  EXPECT_EQ(sprite.sheet->pixel_art->lines, render::SheetParams::PixelArt::Lines::Sprite) << "the default";
  const render::RenderParams drawn = render::pixel_art_frame_params(sprite, *sprite.sheet->pixel_art);
  EXPECT_EQ(drawn.outline.width, 1.0f) << "a silhouette one art pixel wide";
  EXPECT_EQ(drawn.outline.units, render::OutlineUnits::Pixels);
  EXPECT_EQ(drawn.outline.readable_area_px, render::kReadableAreaArtPx);
  EXPECT_TRUE(drawn.outline.whole_pixel_lines);
  EXPECT_FALSE(drawn.contour.enabled);
  EXPECT_EQ(params_of(lines).outline.readable_area_px, 0) << "only pixel art leaves lines out";

  request["sheet"]["pixel_art"]["lines"] = "as_given";
  const render::RenderParams given = params_of(request);
  const render::RenderParams drawn_as_given = render::pixel_art_frame_params(given, *given.sheet->pixel_art);
  EXPECT_EQ(drawn_as_given.outline.width, 3.5f);
  EXPECT_EQ(drawn_as_given.outline.units, render::OutlineUnits::World);
  EXPECT_EQ(drawn_as_given.outline.readable_area_px, 0);
  EXPECT_FALSE(drawn_as_given.outline.whole_pixel_lines);
  EXPECT_TRUE(drawn_as_given.contour.enabled);
}

TEST(PixelArtParams, BadInputsAreRefusedWithTheirPath) {
  const auto& schema = proto::ParamSchema::render_params();
  auto path_of = [&](const json& pixel_art) {
    try {
      const render::RenderParams p = pipeline::render_params_from_wire(
          schema.validate_and_complete({{"width", 48}, {"height", 48}, {"sheet", {{"pixel_art", pixel_art}}}}));
      pipeline::check_sheet_params(p);
    } catch (const RequestError& e) {
      EXPECT_EQ(e.status(), 400) << pixel_art.dump();
      return e.path();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(path_of({{"scale", 5}}), "/sheet/pixel_art/scale") << "48 is not a multiple of 5";
  EXPECT_EQ(path_of({{"scale", 0}}), "/sheet/pixel_art/scale");
  EXPECT_EQ(path_of({{"palette", json::array()}}), "/sheet/pixel_art/palette");
  EXPECT_EQ(path_of({{"palette", {"#ffffff", "red"}}}), "/sheet/pixel_art/palette/1");
  EXPECT_EQ(path_of({{"palette", {"#fffffff"}}}), "/sheet/pixel_art/palette/0");
  EXPECT_EQ(path_of({{"colors", 1}}), "/sheet/pixel_art/colors");
  EXPECT_EQ(path_of({{"dither", "yes"}}), "/sheet/pixel_art/dither");
  EXPECT_EQ(path_of({{"lines", "thin"}}), "/sheet/pixel_art/lines");
  EXPECT_EQ(path_of({{"shades", 4}}), "/sheet/pixel_art/shades");
  EXPECT_EQ(path_of({{"scale", 6}, {"palette", {"#123456"}}, {"dither", true}}), "(accepted)");
  auto layer_path = [&](const std::string& output, const json& sheet) {
    try {
      pipeline::check_sheet_params(pipeline::render_params_from_wire(
          schema.validate_and_complete({{"width", 48}, {"height", 48}, {"output", output}, {"sheet", sheet}})));
    } catch (const RequestError& e) {
      return e.path();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(layer_path("depth", {{"pixel_art", json::object()}}), "/sheet/pixel_art");
  EXPECT_EQ(layer_path("id", {{"animate", true}}), "/sheet/animate");
  EXPECT_EQ(layer_path("lines", {{"animate", true}, {"pixel_art", json::object()}}), "(accepted)");
  EXPECT_EQ(path_of(json::object()), "(accepted)");
}

TEST(PixelArtParams, TheBudgetWeighsTheFramesAsDrawnAndTheWholeAnimation) {
  pipeline::RenderLimits limits;
  limits.max_output_pixels = 64 * 64 * 8;
  limits.max_samples = 64 * 64 * 8;
  // msaa 4 over 8 frames of 64² is four times the sample limit; as pixel
  // art the frames are drawn at 16², one sample each.
  const json sheet = {{"frames", 8}, {"pixel_art", {{"scale", 4}}}};
  EXPECT_NO_THROW(check_budget(params_of({{"width", 64}, {"height", 64}, {"sheet", sheet}}), limits));
  EXPECT_THROW(check_budget(params_of({{"width", 64}, {"height", 64}, {"sheet", {{"frames", 8}}}}), limits),
               LimitError);
  for (const json& over : {json{{"frames", 9}, {"pixel_art", {{"scale", 4}}}}, json{{"frames", 9}, {"animate", true}},
                           json{{"frames", 9}, {"animate", true}, {"pixel_art", json::object()}}}) {
    try {
      check_budget(params_of({{"width", 64}, {"height", 64}, {"sheet", over}}), limits);
      ADD_FAILURE() << over.dump() << " passed a limit of 8 frames of 64²";
    } catch (const LimitError& e) {
      EXPECT_EQ(e.limit(), "--max-output-pixels") << over.dump();
      EXPECT_EQ(e.status(), 422);
    }
  }
}

}  // namespace
}  // namespace toond
