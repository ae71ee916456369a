// Pixel-art sheets and animated sheets over HTTP: tiles made of scale×scale
// blocks on one palette shared by every frame (the given one, or at most
// `colors` computed), each block the palette colour nearest the small
// render's pixel; bad values and limits refused before rendering; and
// `animate` answering a lossless WebP whose frames, read by libwebp's own
// decoder and by Pillow, are the sheet's tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <set>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "support/shared_models.h"
#include "support/webp_frames.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

std::uint32_t rgb_of(const std::uint8_t* p) { return (std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | p[2]; }

// The RGB of every pixel that is not fully transparent.
std::set<std::uint32_t> visible_colours(const image::Image& img) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
    if (img.rgba[i + 3] != 0) colours.insert(rgb_of(&img.rgba[i]));
  }
  return colours;
}

// Whether `tile` is made of k×k blocks of one pixel each, from its corner.
bool whole_blocks(const image::Image& tile, int k) {
  for (int y = 0; y < tile.height; ++y) {
    for (int x = 0; x < tile.width; ++x) {
      if (!std::equal(tile.pixel(x, y), tile.pixel(x, y) + 4, tile.pixel(x - x % k, y - y % k))) return false;
    }
  }
  return true;
}

// Alpha equal everywhere, RGB equal where alpha > 0: what "the same
// pixels" means for an image whose transparent RGB is nobody's concern.
bool same_visible_pixels(const image::Image& a, const image::Image& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i + 3] != b.rgba[i + 3]) return false;
    if (a.rgba[i + 3] != 0 && !std::equal(&a.rgba[i], &a.rgba[i] + 3, &b.rgba[i])) return false;
  }
  return true;
}

class PixelArtSheet : public SharedDaemonTest {
 protected:
  // A request that must succeed, with the content type it must have.
  static std::string body_of(const json& params, const std::string& type, const std::string& path = "/render") {
    auto client = daemon().client();
    auto res = post_json(client, path, params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << path << " answered " << (res ? std::to_string(res->status) + ": " + res->body : "nothing");
      return {};
    }
    EXPECT_EQ(res->get_header_value("Content-Type"), type);
    return res->body;
  }
  static json atlas_of(const json& params) {
    const std::string text = body_of(params, "application/json", "/render?atlas=json");
    return text.empty() ? json::object() : json::parse(text);
  }
};

const json kTransparent = {0, 0, 0, 0};

TEST_F(PixelArtSheet, TilesAreScaleBlocksOnOnePaletteSharedByEveryFrame) {
  const int k = 4, n = 6;
  const json plain = {{"width", 64},
                      {"height", 48},
                      {"background", kTransparent},
                      {"sheet", {{"frames", 8}, {"columns", 4}, {"padding", 2}}}};
  json params = plain;
  params["sheet"]["pixel_art"] = {{"scale", k}, {"colors", n}};
  const std::string png = body_of(params, "image/png");
  ASSERT_FALSE(png.empty());
  const image::Image sheet = image::decode_png(png);
  const json atlas = atlas_of(params);
  EXPECT_EQ(atlas, atlas_of(plain)) << "pixel art leaves the atlas as it is";
  EXPECT_EQ(atlas["meta"]["size"], (json{{"w", sheet.width}, {"h", sheet.height}}));

  std::set<std::uint32_t> every_frame;
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const image::Image tile = tile_of(sheet, frame["frame"]);
    EXPECT_TRUE(whole_blocks(tile, k)) << name << " is not made of " << k << "×" << k << " blocks";
    const std::set<std::uint32_t> colours = visible_colours(tile);
    EXPECT_GE(colours.size(), 2u) << name << " shows the model";
    every_frame.insert(colours.begin(), colours.end());
    EXPECT_EQ(tile.pixel(0, 0)[3], 0) << name << ": the transparent background stays transparent";
  }
  EXPECT_LE(every_frame.size(), static_cast<std::size_t>(n)) << "the frames together use one palette of " << n;
  EXPECT_EQ(sheet.pixel(64, 0)[3], 0) << "padding stays transparent";
}

// Without dithering a block is the palette colour nearest the pixel the
// small render drew: checked against single renders of each view at
// 1/scale, one sample a pixel, band edges hard, under the sheet's framing.
TEST_F(PixelArtSheet, AGivenPaletteIsAllThereIsAndEachBlockItsNearestColour) {
  const int k = 4;
  const std::vector<std::array<int, 3>> palette = {
      {0x20, 0x20, 0x28}, {0xf0, 0xe8, 0xd8}, {0x90, 0x60, 0x40}, {0x50, 0x80, 0xc0}, {0xc0, 0x40, 0x40}};
  json hex = json::array();
  std::set<std::uint32_t> allowed;
  for (const auto& [r, g, b] : palette) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", r, g, b);
    hex.push_back(text);
    allowed.insert((std::uint32_t(r) << 16) | (std::uint32_t(g) << 8) | std::uint32_t(b));
  }
  const json params = {
      {"width", 64},
      {"height", 64},
      {"background", kTransparent},
      // Lines as given: the small renders below draw the request's own.
      {"sheet", {{"frames", 4}, {"pixel_art", {{"scale", k}, {"palette", hex}, {"lines", "as_given"}}}}}};
  const std::string png = body_of(params, "image/png");
  ASSERT_FALSE(png.empty());
  const image::Image sheet = image::decode_png(png);
  for (std::uint32_t c : visible_colours(sheet))
    EXPECT_TRUE(allowed.count(c)) << std::hex << c << " is not in the palette";

  auto nearest = [&](const std::uint8_t* p) {
    std::uint32_t best = 0;
    int best_d = 1 << 30;
    for (const auto& [r, g, b] : palette) {
      const int d = (p[0] - r) * (p[0] - r) + (p[1] - g) * (p[1] - g) + (p[2] - b) * (p[2] - b);
      if (d < best_d) best_d = d, best = (std::uint32_t(r) << 16) | (std::uint32_t(g) << 8) | std::uint32_t(b);
    }
    return best;
  };
  const json atlas = atlas_of(params);
  const double distance = atlas["meta"]["camera"]["distance"];
  auto client = daemon().client();
  std::size_t visible = 0, mismatched = 0;
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const image::Image small = render_ok(
        client, {{"width", 64 / k},
                 {"height", 64 / k},
                 {"background", kTransparent},
                 {"msaa", 1},
                 {"shading", {{"band_aa", false}}},
                 {"camera", {{"yaw", frame["yaw"]}, {"pitch", frame["pitch"]}, {"distance", distance}}},
                 // The sheet's light turns with its camera.
                 {"lights", {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}, {"space", "view"}}}}});
    const image::Image tile = tile_of(sheet, frame["frame"]);
    for (int y = 0; y < small.height; ++y) {
      for (int x = 0; x < small.width; ++x) {
        const std::uint8_t* want = small.pixel(x, y);
        const std::uint8_t* got = tile.pixel(x * k, y * k);
        if (want[3] == 0 && got[3] == 0) continue;
        ++visible;
        if (want[3] != got[3] || rgb_of(got) != nearest(want)) ++mismatched;
      }
    }
  }
  ASSERT_GT(visible, 50u);
  EXPECT_EQ(mismatched, 0u) << "of " << visible << " visible art pixels";
}

// Art pixels of one tile of a pixel-art sheet (one per scale×scale block),
// sorted into background, line colour and the rest.
struct ArtPixels {
  int width = 0, height = 0;
  std::vector<char> kind;  // ' ' background, '#' line, 'o' other
  char at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return ' ';
    return kind[static_cast<std::size_t>(y) * width + x];
  }
};

ArtPixels art_pixels(const image::Image& tile, int scale) {
  ArtPixels art{tile.width / scale, tile.height / scale, {}};
  for (int y = 0; y < art.height; ++y) {
    for (int x = 0; x < art.width; ++x) {
      const std::uint8_t* p = tile.pixel(x * scale, y * scale);
      // The outline's colour is sRGB (15, 13, 20); the characters' darkest
      // shades are far lighter.
      art.kind.push_back(p[3] == 0 ? ' ' : std::max({p[0], p[1], p[2]}) < 40 ? '#' : 'o');
    }
  }
  return art;
}

// Line pixels with no background among their 8 neighbours: crease and
// inner lines, not the silhouette's ring.
int inner_line_pixels(const ArtPixels& art) {
  int inner = 0;
  for (int y = 0; y < art.height; ++y) {
    for (int x = 0; x < art.width; ++x) {
      if (art.at(x, y) != '#') continue;
      bool by_background = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) by_background |= art.at(x + dx, y + dy) == ' ';
      }
      inner += !by_background;
    }
  }
  return inner;
}

// How a pixel-art tile's lines read: the share of the covered art pixels
// that are line, over the whole figure and over its top quarter (a
// character's head), and whether the silhouette is closed.
struct LineShares {
  double whole = 0, top = 0;
  int inner = 0;
  int open_border = 0;  // covered pixels by the background that are not line
};

LineShares line_shares(const ArtPixels& art) {
  int first = art.height, last = -1;
  for (int y = 0; y < art.height; ++y) {
    for (int x = 0; x < art.width; ++x) {
      if (art.at(x, y) != ' ') first = std::min(first, y), last = std::max(last, y);
    }
  }
  LineShares shares;
  int covered = 0, lines = 0, top_covered = 0, top_lines = 0;
  const int top_end = first + (last - first + 1) / 4;
  for (int y = first; y <= last; ++y) {
    for (int x = 0; x < art.width; ++x) {
      const char k = art.at(x, y);
      if (k == ' ') continue;
      ++covered;
      lines += k == '#';
      if (y < top_end) ++top_covered, top_lines += k == '#';
      const bool by_background =
          art.at(x - 1, y) == ' ' || art.at(x + 1, y) == ' ' || art.at(x, y - 1) == ' ' || art.at(x, y + 1) == ' ';
      shares.open_border += by_background && k != '#';
    }
  }
  shares.whole = covered ? double(lines) / covered : 0;
  shares.top = top_covered ? double(top_lines) / top_covered : 0;
  shares.inner = inner_line_pixels(art);
  return shares;
}

// At 32 art pixels, isometric, Blender's blocky walker: sprite lines (the
// default) give a one-pixel silhouette and keep its head mostly its own
// colours, where the request's lines counted in art pixels (a 2-pixel
// outline, crease lines on every block) darkened most of it. Crease lines
// between areas wide enough still show: a big cube keeps its inner edges.
// Measured 0.48-0.56 on the head (a one-pixel ring round a head 4-5 art
// pixels wide is half of it) and 0.41-0.42 overall; the request's own lines
// gave 0.85-0.89 and 0.93, and sprite lines without the 3-pixel rule for
// creases 0.73-0.78 and 0.73-0.74.
constexpr double kSpriteHeadLineShare = 0.6;
constexpr double kSpriteLineShare = 0.5;
// The cube's three crease lines, whole black pixels: 69 measured (as a
// line's share of two pixels they were grey, and none counted).
constexpr int kCubeInnerLines = 40;

TEST_F(PixelArtSheet, SpriteLinesKeepASmallCharacterReadable) {
  auto client = daemon().client();
  const auto uploaded = upload_files(client, TOOND_EXPORTED_DIR "/blender", {"walker.glb"});
  ASSERT_TRUE(uploaded && (uploaded->status == 200 || uploaded->status == 201)) << (uploaded ? uploaded->body : "");
  const std::string walker = json::parse(uploaded->body)["id"];
  const int k = 4;
  auto tiles_of = [&](const std::string& model, const std::string& lines) {
    const json params = {{"model", model},
                         {"width", 128},
                         {"height", 128},
                         {"background", kTransparent},
                         {"camera", {{"preset", "isometric"}}},
                         {"sheet", {{"frames", 4}, {"pixel_art", {{"scale", k}, {"lines", lines}}}}}};
    const image::Image sheet = image::decode_png(body_of(params, "image/png"));
    const json atlas = atlas_of(params);
    std::vector<ArtPixels> tiles;
    for (const auto& [name, frame] : atlas["frames"].items()) {
      tiles.push_back(art_pixels(tile_of(sheet, frame["frame"]), k));
    }
    return tiles;
  };
  const std::vector<ArtPixels> sprite = tiles_of(walker, "sprite");
  const std::vector<ArtPixels> given = tiles_of(walker, "as_given");
  ASSERT_EQ(sprite.size(), 4u);
  ASSERT_EQ(given.size(), 4u);
  for (std::size_t i = 0; i < sprite.size(); ++i) {
    const LineShares s = line_shares(sprite[i]), g = line_shares(given[i]);
    std::printf("walker frame %zu: line share %.2f (head %.2f, inner %d) sprite, %.2f (head %.2f, inner %d) as given\n",
                i, s.whole, s.top, s.inner, g.whole, g.top, g.inner);
    EXPECT_LE(s.top, kSpriteHeadLineShare) << "frame " << i;
    EXPECT_LE(s.whole, kSpriteLineShare) << "frame " << i;
    EXPECT_LT(s.whole, g.whole) << "frame " << i;
    EXPECT_EQ(s.open_border, 0) << "frame " << i << ": the silhouette is closed";
  }

  const std::string cube = upload_obj_text(client, cube_obj(), "cube.obj");
  for (const ArtPixels& tile : tiles_of(cube, "sprite")) {
    EXPECT_GE(inner_line_pixels(tile), kCubeInnerLines) << "the cube's faces are wide enough for their crease lines";
  }
}

// A square rod 0.035 wide and 1 long seen isometrically at 32 art pixels:
// each of its two long faces is about 2 art pixels across, too narrow for
// a crease line between them, so sprite lines leave the rod's own colours
// a run at least 3 art pixels long in every row it crosses. Without that
// rule the crease runs down the whole rod and splits or covers those runs:
// 16 of its rows fall short, and line pixels are 0.81 of it (0.64
// with the rule).
std::string thin_rod_obj() {
  const double half_width = 0.0175, half_length = 0.5;
  std::string obj;
  for (const double x : {-half_length, half_length}) {
    for (const double y : {-half_width, half_width}) {
      for (const double z : {-half_width, half_width}) {
        obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
      }
    }
  }
  // Corner (i, j, k) of x, y, z is vertex 4i + 2j + k + 1; faces wound outward.
  obj += "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";
  return obj;
}

// Rows that show some of the figure's own colours but no run of
// kReadableRun of them side by side.
constexpr int kReadableRun = 3;
int rows_without_a_readable_run(const ArtPixels& art) {
  int short_rows = 0;
  for (int y = 0; y < art.height; ++y) {
    int run = 0, longest = 0;
    for (int x = 0; x < art.width; ++x) {
      run = art.at(x, y) == 'o' ? run + 1 : 0;
      longest = std::max(longest, run);
    }
    short_rows += longest > 0 && longest < kReadableRun;
  }
  return short_rows;
}

TEST_F(PixelArtSheet, SpriteLinesLeaveOutCreasesBetweenAreasTooNarrowToRead) {
  auto client = daemon().client();
  const std::string rod = upload_obj_text(client, thin_rod_obj(), "rod.obj");
  const int k = 4;
  const json params = {{"model", rod},
                       {"width", 128},
                       {"height", 128},
                       {"background", kTransparent},
                       {"camera", {{"preset", "isometric"}}},
                       {"sheet", {{"frames", 1}, {"pixel_art", {{"scale", k}}}}}};
  const image::Image sheet = image::decode_png(body_of(params, "image/png"));
  const ArtPixels art = art_pixels(sheet, k);
  const LineShares shares = line_shares(art);
  const int short_rows = rows_without_a_readable_run(art);
  std::printf("thin rod: %d rows without %d own-colour pixels in a row, line share %.2f\n", short_rows, kReadableRun,
              shares.whole);
  int covered = 0;
  for (const char c : art.kind) covered += c != ' ';
  ASSERT_GT(covered, 60) << "the rod is drawn along the tile";
  std::string picture;
  for (int y = 0; y < art.height; ++y) {
    picture += std::string(art.kind.begin() + y * art.width, art.kind.begin() + (y + 1) * art.width) + "|\n";
  }
  EXPECT_EQ(short_rows, 0) << "no crease line between faces 2 art pixels across:\n" << picture;
  EXPECT_EQ(shares.open_border, 0) << "the silhouette is closed";
}

TEST_F(PixelArtSheet, BadValuesAndLimitsAreRefusedBeforeRendering) {
  auto client = daemon().client();
  struct Case {
    json params;
    int status;
    std::string path;
  };
  const json palette_art = {{"pixel_art", {{"palette", json::array()}}}};
  const json bad_colour_art = {{"pixel_art", {{"palette", {"#12345g"}}}}};
  const json many_pitches = {-60, -40, -20, 0, 20, 40, 60, 80};
  const std::vector<Case> cases = {
      {json{{"width", 50}, {"height", 48}, {"sheet", {{"pixel_art", {{"scale", 4}}}}}}, 400, "/sheet/pixel_art/scale"},
      {json{{"width", 48}, {"height", 50}, {"sheet", {{"pixel_art", {{"scale", 4}}}}}}, 400, "/sheet/pixel_art/scale"},
      {json{{"width", 48}, {"height", 48}, {"sheet", palette_art}}, 400, "/sheet/pixel_art/palette"},
      {json{{"width", 48}, {"height", 48}, {"sheet", bad_colour_art}}, 400, "/sheet/pixel_art/palette/0"},
      {json{{"width", 48}, {"height", 48}, {"sheet", {{"frame_ms", 0}}}}, 400, "/sheet/frame_ms"},
      // 64 frames × 8 pitches of 512² is over the default --max-output-pixels
      // (4096²), as pixel art and as an animation alike.
      {json{{"sheet", {{"frames", 64}, {"pitches", many_pitches}, {"pixel_art", json::object()}}}}, 422,
       "/sheet/frames"},
      {json{{"sheet", {{"frames", 64}, {"pitches", many_pitches}, {"animate", true}}}}, 422, "/sheet/frames"},
  };

  for (const Case& c : cases) {
    auto res = post_json(client, "/render", c.params);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, c.status) << c.params.dump() << ": " << res->body;
    EXPECT_EQ(error_of(res)["path"], c.path) << c.params.dump();
  }
}

TEST_F(PixelArtSheet, AnimateAnswersALosslessWebpOfTheSheetsTiles) {
  const json sheet_params = {{"width", 48},
                             {"height", 40},
                             {"background", kTransparent},
                             {"sheet", {{"frames", 6}, {"columns", 3}, {"pitches", {10, 40}}, {"padding", 1}}}};
  json params = sheet_params;
  params["sheet"]["animate"] = true;
  params["sheet"]["frame_ms"] = 80;
  const std::string webp = body_of(params, "image/webp");
  ASSERT_FALSE(webp.empty());
  const image::Image sheet = image::decode_png(body_of(sheet_params, "image/png"));
  const json atlas = atlas_of(params);
  EXPECT_EQ(atlas["meta"]["image"], "sheet.webp");

  const WebpFrames decoded = decode_webp_frames(webp);
  EXPECT_EQ(decoded.loop_count, 0) << "loops forever";
  ASSERT_EQ(decoded.frames.size(), 12u) << "6 frames × 2 pitches";
  for (std::size_t i = 0; i < decoded.frames.size(); ++i) {
    // Pitch by pitch: frames 0 .. 5 at pitch 10, then pitch 40.
    const std::string name = std::to_string(i);
    const json& frame = atlas["frames"][name];
    EXPECT_EQ(frame["pitch"].get<double>(), i < 6 ? 10 : 40) << name;
    EXPECT_TRUE(same_visible_pixels(decoded.frames[i], tile_of(sheet, frame["frame"])))
        << "animation frame " << i << " differs from the sheet's " << name;
    EXPECT_EQ(decoded.end_ms[i], static_cast<int>(i + 1) * 80);
  }

  // Answered again (from the result cache where it is on): still WebP.
  auto client = daemon().client();
  auto again = post_json(client, "/render", params);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->get_header_value("Content-Type"), "image/webp");
  EXPECT_EQ(again->body, webp);
}

TEST_F(PixelArtSheet, AnimatedPixelArtIsBlocksOnOnePaletteInEveryFrame) {
  const json params = {{"width", 64},
                       {"height", 64},
                       {"background", kTransparent},
                       {"sheet", {{"frames", 8}, {"animate", true}, {"pixel_art", {{"scale", 8}, {"colors", 4}}}}}};
  const std::string webp = body_of(params, "image/webp");
  ASSERT_FALSE(webp.empty());
  const WebpFrames decoded = decode_webp_frames(webp);
  ASSERT_EQ(decoded.frames.size(), 8u);
  // The same frames as the pixel-art sheet's tiles (one palette, computed
  // over the same small frames).
  json sheet_params = params;
  sheet_params["sheet"].erase("animate");
  const image::Image sheet = image::decode_png(body_of(sheet_params, "image/png"));
  const json atlas = atlas_of(sheet_params);
  std::set<std::uint32_t> every_frame;
  for (std::size_t i = 0; i < decoded.frames.size(); ++i) {
    const image::Image& frame = decoded.frames[i];
    const std::string name = std::to_string(i);
    EXPECT_TRUE(same_visible_pixels(frame, tile_of(sheet, atlas["frames"][name]["frame"]))) << name;
    EXPECT_TRUE(whole_blocks(frame, 8));
    const std::set<std::uint32_t> colours = visible_colours(frame);
    EXPECT_GE(colours.size(), 2u) << "every frame shows the model in more than one colour";
    every_frame.insert(colours.begin(), colours.end());
  }
  EXPECT_LE(every_frame.size(), 4u);
}

// Pillow, not libwebp through our own test code, opens the animation.
TEST_F(PixelArtSheet, PillowOpensTheAnimationWithEveryFrame) {
  const auto probe =
      run_process({"/usr/bin/python3", "-c", "from PIL import features; assert features.check('webp_anim')"});
  if (probe.status != 0) GTEST_SKIP() << "/usr/bin/python3 with Pillow's animated WebP is absent (Debian: python3-pil)";
  const std::string webp =
      body_of({{"width", 32}, {"height", 32}, {"sheet", {{"frames", 5}, {"animate", true}}}}, "image/webp");
  ASSERT_FALSE(webp.empty());
  const auto file = make_temp_dir("toond-anim") / "turntable.webp";
  std::ofstream(file, std::ios::binary) << webp;
  const auto r = run_process({"/usr/bin/python3", "-c",
                              "import sys, json\n"
                              "from PIL import Image\n"
                              "im = Image.open(sys.argv[1])\n"
                              "print(json.dumps({'format': im.format, 'size': list(im.size), 'frames': im.n_frames,"
                              " 'animated': im.is_animated, 'loop': im.info.get('loop')}))\n",
                              file.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out),
            (json{{"format", "WEBP"}, {"size", {32, 32}}, {"frames", 5}, {"animated", true}, {"loop", 0}}));
}

TEST_F(PixelArtSheet, TheCliWritesTheWebpItIsAnswered) {
  const auto out = make_temp_dir("toon-anim") / "turntable.webp";
  // Thirds of a turn: the demo model looks alike every quarter turn, and a
  // sheet's light turns with it, so quarters would be one frame, merged.
  const auto r = run_process({TOON_BINARY, "render", "--set", "sheet.frames=3", "--set", "sheet.animate=true", "--set",
                              "sheet.pixel_art.scale=2", "--set", "width=32", "--set", "height=32", "-o", out.string(),
                              "--server", daemon().url()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string bytes = read_file(out);
  ASSERT_GE(bytes.size(), 12u);
  EXPECT_EQ(bytes.substr(0, 4), "RIFF");
  EXPECT_EQ(bytes.substr(8, 4), "WEBP");
  EXPECT_EQ(decode_webp_frames(bytes).frames.size(), 3u);
}

}  // namespace
}  // namespace toond::test
