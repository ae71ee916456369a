// Sprite sheets over HTTP: each tile is the single render of its view under
// the framing all frames share, the atlas describes the PNG it rides in,
// limits refuse before rendering, and another decoder reads the result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "support/golden_compare.h"
#include "support/image_checks.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

// Rows from the model's top to its bottom: the pixels unlike the corner.
int silhouette_height(const image::Image& img) {
  const std::vector<bool> mask = foreground_mask(img);
  int top = img.height, bottom = -1;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (mask[static_cast<std::size_t>(y) * img.width + x]) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  }
  return bottom < top ? 0 : bottom - top + 1;
}

class Sheet : public SharedDaemonTest {
 protected:
  // The sheet's PNG bytes, from a request that must succeed.
  static std::string sheet_png(const json& params, const std::string& path = "/render") {
    auto client = daemon().client();
    auto res = post_json(client, path, params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << path << " answered " << (res ? std::to_string(res->status) + ": " + res->body : "nothing");
      return {};
    }
    EXPECT_EQ(res->get_header_value("Content-Type"), "image/png");
    EXPECT_FALSE(res->get_header_value("X-Toond-Passes").empty());
    EXPECT_FALSE(res->get_header_value("X-Toond-Lod").empty());
    return res->body;
  }
  static json atlas_of(const std::string& png) {
    const std::optional<std::string> text = png_text(png, "toond:atlas");
    if (!text) {
      ADD_FAILURE() << "the PNG has no tEXt chunk toond:atlas";
      return json::object();
    }
    return json::parse(*text);
  }
};

// A sheet's lights turn with its camera (lights[].space view, its default);
// a single render asks for the same with space view and the atlas's
// distance, in perspective and in the orthographic sprite presets, where
// the distance sizes the view.
TEST_F(Sheet, EachTileIsTheSingleRenderOfItsViewUnderTheSharedFraming) {
  const json view_light = {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}, {"space", "view"}}};
  for (const json& camera : {json::object(), json{{"preset", "dimetric"}}, json{{"preset", "isometric"}}}) {
    const json params = {{"width", 64},
                         {"height", 64},
                         {"camera", camera},
                         {"sheet", {{"frames", 8}, {"columns", 4}, {"pitches", {15, 40}}}}};
    const std::string png = sheet_png(params);
    ASSERT_FALSE(png.empty());
    const image::Image sheet = image::decode_png(png);
    const json atlas = atlas_of(png);
    ASSERT_EQ(atlas["frames"].size(), 16u);
    const double distance = atlas["meta"]["camera"]["distance"];
    auto client = daemon().client();
    for (const auto& [name, frame] : atlas["frames"].items()) {
      json view = camera;
      view.update({{"yaw", frame["yaw"]}, {"pitch", frame["pitch"]}, {"distance", distance}});
      const image::Image single =
          render_ok(client, {{"width", 64}, {"height", 64}, {"camera", view}, {"lights", view_light}});
      const GoldenDiff diff = compare_golden(single, tile_of(sheet, frame["frame"]));
      EXPECT_TRUE(diff.passes()) << camera.dump() << " frame " << name << " (yaw " << frame["yaw"] << ", pitch "
                                 << frame["pitch"] << "): " << diff.pixels_over << " pixels differ by more than "
                                 << kGoldenLevels << " levels, largest " << diff.largest;
    }
  }
}

// A cube seen side-on and corner-on, orthographic at pitch 0: its height on
// screen only changes if the framing does. Framed alone, the corner-on view
// must back off for the cube's diagonal; in a sheet every frame keeps one
// scale.
TEST_F(Sheet, TheModelKeepsItsSizeFromFrameToFrame) {
  auto client = daemon().client();
  const std::string cube = upload_obj_text(client, cube_obj(1.0), "cube.obj");
  ASSERT_FALSE(cube.empty());
  const json camera = {{"projection", "orthographic"}, {"pitch", 0}, {"yaw", 0}};
  const json base = {{"model", cube}, {"width", 64}, {"height", 64}, {"camera", camera}};

  json corner_on = base;
  corner_on["camera"]["yaw"] = 45;
  const int alone_side = silhouette_height(render_ok(client, base));
  const int alone_corner = silhouette_height(render_ok(client, corner_on));
  ASSERT_GT(alone_side - alone_corner, 8) << "framed alone, the views differ in scale; the check below needs that";

  json params = base;
  params["sheet"] = {{"frames", 8}};
  const std::string png = sheet_png(params, "/models/" + cube + "/render");
  ASSERT_FALSE(png.empty());
  const image::Image sheet = image::decode_png(png);
  const json atlas = atlas_of(png);
  std::set<int> heights;
  for (const auto& [name, frame] : atlas["frames"].items())
    heights.insert(silhouette_height(tile_of(sheet, frame["frame"])));
  ASSERT_FALSE(heights.empty());
  EXPECT_LE(*heights.rbegin() - *heights.begin(), 1)
      << "tile heights from " << *heights.begin() << " to " << *heights.rbegin();
  EXPECT_NEAR(*heights.begin(), alone_corner, 1) << "every frame has the scale of the widest view";
}

TEST_F(Sheet, TheAtlasDescribesTheSheetItRidesIn) {
  const json params = {{"width", 40},
                       {"height", 32},
                       {"camera", {{"preset", "isometric"}}},
                       {"sheet", {{"frames", 8}, {"columns", 3}, {"yaw_start", 0}, {"padding", 2}}}};
  const std::string png = sheet_png(params);
  ASSERT_FALSE(png.empty());
  const image::Image sheet = image::decode_png(png);
  const json atlas = atlas_of(png);
  ASSERT_TRUE(atlas.contains("frames") && atlas.contains("meta"));
  EXPECT_EQ(atlas["meta"]["size"], (json{{"w", sheet.width}, {"h", sheet.height}}));
  EXPECT_EQ(sheet.width, 3 * 40 + 2 * 2);
  EXPECT_EQ(sheet.height, 3 * 32 + 2 * 2);
  EXPECT_EQ(atlas["meta"]["padding"], 2);
  EXPECT_FALSE(atlas["meta"]["image"].get<std::string>().empty());
  EXPECT_EQ(atlas["meta"]["camera"]["projection"], "orthographic");

  ASSERT_EQ(atlas["frames"].size(), 8u);
  std::set<std::pair<int, int>> covered;
  std::set<double> yaws;
  for (const auto& [name, frame] : atlas["frames"].items()) {
    for (const char* key : {"frame", "spriteSourceSize", "sourceSize", "pivot", "rotated", "trimmed", "yaw", "pitch"}) {
      EXPECT_TRUE(frame.contains(key)) << name << " lacks " << key;
    }
    const json& r = frame["frame"];
    EXPECT_EQ(r["w"], 40);
    EXPECT_EQ(r["h"], 32);
    EXPECT_EQ(frame["sourceSize"], (json{{"w", 40}, {"h", 32}}));
    EXPECT_LE(r["x"].get<int>() + 40, sheet.width);
    EXPECT_LE(r["y"].get<int>() + 32, sheet.height);
    for (int y = r["y"]; y < r["y"].get<int>() + 32; ++y) {
      for (int x = r["x"]; x < r["x"].get<int>() + 40; ++x) {
        EXPECT_TRUE(covered.insert({x, y}).second) << name << " overlaps another frame at " << x << "," << y;
      }
    }
    EXPECT_NEAR(frame["pitch"].get<double>(), 35.264, 1e-9) << "the isometric preset's pitch";
    yaws.insert(frame["yaw"].get<double>());
  }
  EXPECT_EQ(yaws, (std::set<double>{0, 45, 90, 135, 180, 225, 270, 315}));
  // Padding and the empty cell after the last frame are transparent.
  EXPECT_EQ(sheet.pixel(40, 0)[3], 0);
  EXPECT_EQ(sheet.pixel(sheet.width - 1, sheet.height - 1)[3], 0);

  auto client = daemon().client();
  auto alone = post_json(client, "/render?atlas=json", params);
  ASSERT_TRUE(alone);
  ASSERT_EQ(alone->status, 200) << alone->body;
  EXPECT_EQ(alone->get_header_value("Content-Type"), "application/json");
  EXPECT_EQ(json::parse(alone->body), atlas);
}

TEST_F(Sheet, LimitsAndBadValuesAreRefusedBeforeRendering) {
  auto client = daemon().client();
  // 64 frames × 8 pitches of 512² is 134 M pixels, over the default
  // --max-output-pixels (4096²) that any single 512² render is far within.
  auto over =
      post_json(client, "/render", {{"sheet", {{"frames", 64}, {"pitches", {-60, -40, -20, 0, 20, 40, 60, 80}}}}});
  ASSERT_TRUE(over);
  EXPECT_EQ(over->status, 422) << over->body;
  EXPECT_EQ(error_of(over)["code"], "limit_exceeded");
  EXPECT_EQ(error_of(over)["limit"], "--max-output-pixels");

  for (const json& bad : {json{{"frames", 0}}, json{{"columns", 0}}, json{{"pitches", json::array()}},
                          json{{"yaw_step", 400}}, json{{"loop", true}}}) {
    auto res = post_json(client, "/render", {{"width", 32}, {"height", 32}, {"sheet", bad}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << bad.dump() << ": " << res->body;
    EXPECT_EQ(error_of(res)["path"].get<std::string>().rfind("/sheet/", 0), 0u) << bad.dump();
  }
  auto not_json = post_json(client, "/render?atlas=xml", {{"width", 32}, {"height", 32}, {"sheet", {{"frames", 2}}}});
  ASSERT_TRUE(not_json);
  EXPECT_EQ(not_json->status, 400);
  auto no_sheet = post_json(client, "/render?atlas=json", {{"width", 32}, {"height", 32}});
  ASSERT_TRUE(no_sheet);
  EXPECT_EQ(no_sheet->status, 400);
  EXPECT_EQ(error_of(no_sheet)["path"], "/sheet");
}

// Python's PIL, not libpng through our own codec, reads the sheet and the
// atlas chunk (Image.text holds a PNG's tEXt chunks).
TEST_F(Sheet, AnotherDecoderReadsTheSheetAndItsAtlas) {
  const auto probe = run_process({"/usr/bin/python3", "-c", "import PIL"});
  if (probe.status != 0) GTEST_SKIP() << "/usr/bin/python3 with PIL is absent (Debian: python3-pil)";
  const std::string png = sheet_png({{"width", 48}, {"height", 48}, {"sheet", {{"frames", 4}, {"columns", 2}}}});
  ASSERT_FALSE(png.empty());
  const auto file = make_temp_dir("toond-sheet") / "sheet.png";
  std::ofstream(file, std::ios::binary) << png;
  // The encoder picks palette, RGB or RGBA by content: PIL's pixels, made
  // RGBA, must be our decoder's bytes whichever it chose.
  const auto pixels = file.parent_path() / "sheet.rgba";
  const auto r = run_process({"/usr/bin/python3", "-c",
                              "import sys, json\n"
                              "from PIL import Image\n"
                              "im = Image.open(sys.argv[1]); im.load()\n"
                              "open(sys.argv[2], 'wb').write(im.convert('RGBA').tobytes())\n"
                              "print(json.dumps({'size': list(im.size),"
                              " 'atlas': json.loads(im.text['toond:atlas'])}))\n",
                              file.string(), pixels.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const json seen = json::parse(r.out);
  EXPECT_EQ(seen["size"], (json{96, 96}));
  EXPECT_EQ(seen["atlas"], atlas_of(png));
  std::ifstream in(pixels, std::ios::binary);
  const std::string theirs((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const image::Image ours = image::decode_png(png);
  EXPECT_TRUE(theirs.size() == ours.rgba.size() &&
              std::equal(ours.rgba.begin(), ours.rgba.end(), theirs.begin(),
                         [](std::uint8_t a, char b) { return a == static_cast<std::uint8_t>(b); }))
      << "PIL's pixels differ from the sheet's";
}

TEST_F(Sheet, TheCliAsksForASheetWithSet) {
  const auto png = make_temp_dir("toon-sheet") / "sheet.png";
  const auto r = run_process({TOON_BINARY, "render", "--set", "sheet.frames=8", "--set", "width=32", "--set",
                              "height=32", "-o", png.string(), "--server", daemon().url()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string bytes = read_file(png);
  const image::Image sheet = image::decode_png(bytes);
  EXPECT_EQ(sheet.width, 8 * 32);
  EXPECT_EQ(sheet.height, 32);
  EXPECT_EQ(atlas_of(bytes)["frames"].size(), 8u);
}

// The light's space from the CLI: `--set lights.0.space=view` turns the
// default light with the camera, so seen from behind (yaw 180) the single
// render is lit as the front of a view-lit sheet is, and differs from the
// model-lit one; a space the schema does not know is refused before sending.
TEST_F(Sheet, TheCliSetsTheLightsSpace) {
  const auto dir = make_temp_dir("toon-light-space");
  const auto cli = [&](const std::string& space, const std::string& out) {
    return run_process({TOON_BINARY, "render", "--set", "lights.0.space=" + space, "--set", "camera.yaw=180", "--set",
                        "width=48", "--set", "height=48", "-o", (dir / out).string(), "--server", daemon().url()});
  };
  const auto view = cli("view", "view.png");
  ASSERT_EQ(view.status, 0) << view.err;
  const auto model = cli("model", "model.png");
  ASSERT_EQ(model.status, 0) << model.err;
  auto client = daemon().client();
  const json light = {{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}, {"space", "view"}};
  const image::Image asked =
      render_ok(client, {{"width", 48}, {"height", 48}, {"camera", {{"yaw", 180}}}, {"lights", {light}}});
  EXPECT_EQ(image::decode_png(read_file(dir / "view.png")).rgba, asked.rgba);
  EXPECT_NE(image::decode_png(read_file(dir / "model.png")).rgba, asked.rgba);
  const auto bad = cli("world", "bad.png");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("lights"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace toond::test
