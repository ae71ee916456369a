// Clip ranges and one-shot clips through the daemon, on files no one here
// made: Minetest's player (tests/exported/minetest: its B3D keeps every
// action on one 220-frame timeline, the walk at frames 168-187) and
// Blender's glTF of the same .blend, and Blender's bending bar
// (tests/exported/blender/rigged.gltf) for the errors and the animated
// WebP. Every render is the default request (no lod, no msaa).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "image/png_codec.h"
#include "support/golden_compare.h"
#include "support/shared_models.h"
#include "support/webp_frames.h"
#include "test_client.h"

namespace toond::test {
namespace {

using json = nlohmann::json;

constexpr int kTile = 96;
constexpr int kDirections = 4;
constexpr int kFrames = 8;
// Minetest's walk (player_api/init.lua), in frames of the timeline.
constexpr double kWalkFirst = 168, kWalkLast = 187;

// The light a sheet has by default, turning with its camera: a single
// render given it draws a tile's pixels.
const json kViewLight = {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}, {"space", "view"}}};

struct RangeModel {
  std::string id;
  json clip;  // the upload answer's first clip
};

RangeModel upload_with_clip(httplib::Client& client, const std::string& folder, const std::vector<std::string>& files) {
  const auto res = upload_files(client, folder, files);
  if (!res || (res->status != 200 && res->status != 201)) {
    ADD_FAILURE() << (res ? res->body : "no answer");
    return {};
  }
  const json info = json::parse(res->body);
  if (info["animation"]["clips"].empty()) {
    ADD_FAILURE() << "no clips: " << info.dump();
    return {};
  }
  return {info["id"], info["animation"]["clips"][0]};
}

class ClipRange : public SharedDaemonTest {
 protected:
  static httplib::Client client() { return daemon().client(); }
  static const RangeModel& minetest() {
    static const RangeModel model = [] {
      auto c = client();
      return upload_with_clip(c, TOOND_EXPORTED_DIR "/minetest", {"character.b3d", "character.png"});
    }();
    return model;
  }
  static const RangeModel& blender_twin() {
    static const RangeModel model = [] {
      auto c = client();
      return upload_with_clip(c, TOOND_EXPORTED_DIR "/minetest", {"character_blender.glb"});
    }();
    return model;
  }
  static const std::string& bar() {
    static const std::string id = [] {
      auto c = client();
      return upload_with_clip(c, TOOND_EXPORTED_DIR "/blender", {"rigged.gltf", "rigged.bin"}).id;
    }();
    return id;
  }
  static json atlas_of(const json& params) {
    auto c = client();
    const auto res = post_json(c, "/render?atlas=json", params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << (res ? std::to_string(res->status) + ": " + res->body : "no answer");
      return json::object();
    }
    return json::parse(res->body);
  }
  static image::Image sheet_of(const json& params) {
    auto c = client();
    return render_ok(c, params);
  }
  // The single render of clip 0 at `time` of `range` from the view of the
  // sheet's `frame`, framed as the sheet's `atlas` says: its tile, if the
  // sheet drew that pose.
  static image::Image single_render(const std::string& model, const json& atlas, const json& frame, const json& range,
                                    double time) {
    auto c = client();
    const json camera = {
        {"yaw", frame["yaw"]}, {"pitch", frame["pitch"]}, {"distance", atlas["meta"]["camera"]["distance"]}};
    return render_ok(c, {{"model", model},
                         {"width", kTile},
                         {"height", kTile},
                         {"background", {0, 0, 0, 0}},
                         {"camera", camera},
                         {"lights", kViewLight},
                         {"animation", {{"clip", 0}, {"range", range}, {"time", time}}}});
  }
};

// A sheet of `clip` over `range` (absent: the whole clip), 4 directions
// from yaw 0, on a transparent background.
json sheet_request(const std::string& model, const json& clip) {
  return {{"model", model},
          {"width", kTile},
          {"height", kTile},
          {"background", {0, 0, 0, 0}},
          {"sheet", {{"frames", kDirections}, {"yaw_start", 0}, {"animation", clip}}}};
}

json walk_range(double frame_rate) { return {kWalkFirst / frame_rate, kWalkLast / frame_rate}; }

// The pixels anything is drawn on (alpha above 0).
std::vector<bool> alpha_mask(const image::Image& img) {
  std::vector<bool> mask(static_cast<std::size_t>(img.width) * img.height);
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = img.rgba[4 * i + 3] > 0;
  return mask;
}

// The drawn pixels' bounding box, as shares of the tile's width and height.
struct Extent {
  double width = 0, height = 0;
};
Extent extent_of(const image::Image& img) {
  int x0 = img.width, y0 = img.height, x1 = -1, y1 = -1;
  const std::vector<bool> mask = alpha_mask(img);
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (!mask[static_cast<std::size_t>(y) * img.width + x]) continue;
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return {};
  return {(x1 - x0 + 1) / static_cast<double>(img.width), (y1 - y0 + 1) / static_cast<double>(img.height)};
}

// Intersection over union of two silhouettes.
double silhouette_overlap(const std::vector<bool>& a, const std::vector<bool>& b) {
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < a.size(); ++i) both += a[i] && b[i], either += a[i] || b[i];
  return either ? static_cast<double>(both) / static_cast<double>(either) : 1.0;
}

std::size_t mask_difference(const std::vector<bool>& a, const std::vector<bool>& b) {
  std::size_t apart = 0;
  for (std::size_t i = 0; i < a.size(); ++i) apart += a[i] != b[i];
  return apart;
}

// The tiles of a sheet in atlas order (frames "0", "1", …).
std::vector<image::Image> sheet_tiles(const image::Image& sheet, const json& atlas) {
  std::vector<image::Image> tiles;
  for (std::size_t i = 0; i < atlas["frames"].size(); ++i)
    tiles.push_back(tile_of(sheet, atlas["frames"][std::to_string(i)]["frame"]));
  return tiles;
}

// ---- Minetest's walk ---------------------------------------------------------

// The Done-when of issue 45: Minetest's player as uploaded (its clip lists
// the B3D's 60 frames a second), a sheet of its walk range, 4 directions ×
// 8 frames: the frames differ (it walks), each tile's silhouette fills its
// tile (framed by the walk, not by the whole timeline, whose lying-down
// frames halve it), and each tile poses as Blender's glTF of the same
// .blend does at the same frames. Blender's glTF keys the scene's frame f
// at f / 30 s (the .blend's 30 frames a second; its clip runs 220 / 30 s),
// the B3D at f / 60 s (the rate its file states).
TEST_F(ClipRange, MinetestsWalkSheetMovesFillsItsTilesAndPosesLikeBlendersGltf) {
  const RangeModel& b3d = minetest();
  const RangeModel& gltf = blender_twin();
  ASSERT_FALSE(b3d.id.empty() || gltf.id.empty());
  ASSERT_TRUE(b3d.clip.contains("frame_rate")) << b3d.clip;
  const double frame_rate = b3d.clip["frame_rate"];
  EXPECT_EQ(frame_rate, 60.0);
  EXPECT_FALSE(gltf.clip.contains("frame_rate")) << "glTF keys by seconds";
  EXPECT_NEAR(gltf.clip["duration"].get<double>(), 220.0 / 30.0, 1e-4) << "Blender's 220 frames at 30 a second";

  const json walk = {{"clip", 0}, {"frames", kFrames}, {"range", walk_range(frame_rate)}};
  const json request = sheet_request(b3d.id, walk);
  const json atlas = atlas_of(request);
  ASSERT_EQ(atlas["frames"].size(), static_cast<std::size_t>(kDirections * kFrames));
  EXPECT_NEAR(atlas["frames"]["0"]["time"].get<double>(), kWalkFirst / 60.0, 1e-12);
  EXPECT_NEAR(atlas["frames"]["7"]["time"].get<double>(), (kWalkFirst + 7.0 / 8.0 * (kWalkLast - kWalkFirst)) / 60.0,
              1e-12);
  const std::vector<image::Image> tiles = sheet_tiles(sheet_of(request), atlas);
  const std::vector<image::Image> whole_timeline =
      sheet_tiles(sheet_of(sheet_request(b3d.id, {{"clip", 0}, {"frames", kFrames}})), atlas);
  json twin_walk = walk;
  twin_walk["range"] = walk_range(30.0);
  const std::vector<image::Image> twin = sheet_tiles(sheet_of(sheet_request(gltf.id, twin_walk)), atlas);
  ASSERT_EQ(tiles.size(), twin.size());
  ASSERT_EQ(tiles.size(), whole_timeline.size());

  // It walks: within each direction, each frame's silhouette differs from
  // the next one's (the last's from the first's: the walk loops).
  std::size_t least_apart = tiles[0].rgba.size();
  for (int d = 0; d < kDirections; ++d) {
    for (int k = 0; k < kFrames; ++k) {
      const std::size_t apart =
          mask_difference(alpha_mask(tiles[static_cast<std::size_t>(d * kFrames + k)]),
                          alpha_mask(tiles[static_cast<std::size_t>(d * kFrames + (k + 1) % kFrames)]));
      least_apart = std::min(least_apart, apart);
      EXPECT_GE(apart, 20u) << "direction " << d << ": frame " << k << " and the next are alike";
    }
  }
  // It fills its tile: the walk's framing against the whole timeline's.
  double least_height = 1, least_gain = 1e9, most_whole = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const Extent walking = extent_of(tiles[i]), whole = extent_of(whole_timeline[i]);
    least_height = std::min(least_height, walking.height);
    most_whole = std::max(most_whole, whole.height);
    least_gain = std::min(least_gain, walking.height / whole.height);
    EXPECT_GE(walking.height, 0.75) << "tile " << i << " is " << walking.height << " of its tile's height";
    EXPECT_GE(walking.height, 1.4 * whole.height) << "tile " << i;
  }
  // It poses as Blender's glTF does at the same frames; a frame apart, it
  // would not (the measure sees the pose).
  constexpr double kLeastOverlap = 0.9;
  double least_overlap = 1, most_a_frame_apart = 0;
  std::size_t pixels_off = 0;
  int below = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const double o = silhouette_overlap(alpha_mask(tiles[i]), alpha_mask(twin[i]));
    least_overlap = std::min(least_overlap, o);
    below += o < kLeastOverlap;
    pixels_off += mask_difference(alpha_mask(tiles[i]), alpha_mask(twin[i]));
    const std::size_t next = i - i % kFrames + (i + 1) % kFrames;
    most_a_frame_apart = std::max(most_a_frame_apart, silhouette_overlap(alpha_mask(tiles[i]), alpha_mask(twin[next])));
  }
  EXPECT_EQ(below, 0) << "tiles whose silhouette overlaps the glTF's below " << kLeastOverlap << "; least "
                      << least_overlap;
  EXPECT_GT(least_overlap, most_a_frame_apart) << "the same frames overlap no better than neighbouring ones";
  std::printf(
      "walk sheet, %d tiles: least silhouette difference between neighbouring frames %zu px; "
      "bounding box height least %.3f of the tile (whole timeline framed: at most %.3f; least gain %.2fx); "
      "silhouette overlap with Blender's glTF least %.4f, %d tile(s) below %.2f, %zu pixels differ in all "
      "(a frame apart: at most %.4f)\n",
      static_cast<int>(tiles.size()), least_apart, least_height, most_whole, least_gain, least_overlap, below,
      kLeastOverlap, pixels_off, most_a_frame_apart);
}

// `time` counts from the range's start and wraps inside it: a tile of the
// walk sheet is the single render of its time a whole walk later, or
// earlier, framed by the range.
TEST_F(ClipRange, ATimePastTheRangeWrapsInsideIt) {
  const RangeModel& b3d = minetest();
  ASSERT_FALSE(b3d.id.empty());
  const json range = walk_range(b3d.clip["frame_rate"].get<double>());
  const double length = range[1].get<double>() - range[0].get<double>();
  const json request = sheet_request(b3d.id, {{"clip", 0}, {"frames", kFrames}, {"range", range}});
  const json atlas = atlas_of(request);
  const std::vector<image::Image> tiles = sheet_tiles(sheet_of(request), atlas);
  const auto single = [&](const json& frame, double time) { return single_render(b3d.id, atlas, frame, range, time); };
  for (const int k : {0, 3, 6}) {
    const json& frame = atlas["frames"][std::to_string(k)];
    const double into = frame["time"].get<double>() - range[0].get<double>();
    for (const double time : {into, into + length, into + 3 * length, into - 2 * length}) {
      const GoldenDiff diff = compare_golden(single(frame, time), tiles[static_cast<std::size_t>(k)]);
      EXPECT_TRUE(diff.passes()) << "frame " << k << " at time " << time << ": " << diff.pixels_over
                                 << " pixels differ, largest " << diff.largest;
    }
  }
  // The range's end is its start again.
  const json& first = atlas["frames"]["0"];
  EXPECT_EQ(single(first, length).rgba, single(first, 0.0).rgba);
}

// loop: false draws a one-shot to its last pose: a sheet's last frame is
// the range's end (the single render just short of it: a time of the
// range's length is its start again), where the loop's last frame stops
// a step short. Over the walk and over its first quarter stride (frames
// 168-173: feet together to apart), whose end is another pose than its
// start.
TEST_F(ClipRange, AOneShotEndsOnTheRangesLastPose) {
  const RangeModel& b3d = minetest();
  ASSERT_FALSE(b3d.id.empty());
  const double frame_rate = b3d.clip["frame_rate"];
  for (const json& range : {walk_range(frame_rate), json{kWalkFirst / frame_rate, (kWalkFirst + 5) / frame_rate}}) {
    const double length = range[1].get<double>() - range[0].get<double>();
    const json once = sheet_request(b3d.id, {{"clip", 0}, {"frames", kFrames}, {"range", range}, {"loop", false}});
    const json atlas = atlas_of(once);
    const std::vector<image::Image> tiles = sheet_tiles(sheet_of(once), atlas);
    ASSERT_EQ(tiles.size(), static_cast<std::size_t>(kDirections * kFrames));
    const json& last = atlas["frames"][std::to_string(kFrames - 1)];
    EXPECT_DOUBLE_EQ(last["time"].get<double>(), range[1].get<double>());
    EXPECT_EQ(atlas["meta"]["frameTags"][0]["repeat"], "1");
    const auto single = [&](double time) { return single_render(b3d.id, atlas, last, range, time); };
    const image::Image at_end = single(length - 1e-9);
    const GoldenDiff end_diff = compare_golden(at_end, tiles[kFrames - 1]);
    EXPECT_TRUE(end_diff.passes()) << range << ": the last tile is not the range's end: " << end_diff.pixels_over
                                   << " pixels differ, largest " << end_diff.largest;
    const GoldenDiff start_diff = compare_golden(single(0.0), tiles[0]);
    EXPECT_TRUE(start_diff.passes()) << range << ": the first tile is not the range's start";
    // The loop's last frame is a step short of the end.
    const json looped = sheet_request(b3d.id, {{"clip", 0}, {"frames", kFrames}, {"range", range}});
    const std::vector<image::Image> loop_tiles = sheet_tiles(sheet_of(looped), atlas_of(looped));
    EXPECT_GT(mask_difference(alpha_mask(loop_tiles[kFrames - 1]), alpha_mask(at_end)), 20u) << range;
    if (range[1].get<double>() < walk_range(frame_rate)[1].get<double>()) {
      EXPECT_GT(mask_difference(alpha_mask(tiles[0]), alpha_mask(tiles[kFrames - 1])), 50u)
          << range << ": the quarter stride ends where it starts";
    }
    std::printf(
        "range [%.4f, %.4f] s: one-shot's last tile vs the range's end: %zu pixels over; first vs last "
        "tile silhouettes %zu px apart\n",
        range[0].get<double>(), range[1].get<double>(), end_diff.pixels_over,
        mask_difference(alpha_mask(tiles[0]), alpha_mask(tiles[kFrames - 1])));
  }
}

// ---- the animated WebP ---------------------------------------------------------

// A one-shot sheet as an animated WebP: each direction plays the clip once,
// from its start to its last pose, each frame for its step; the whole plays
// once (loop count 1) and stays on the last direction's last pose. A sheet
// with a looping clip among its clips loops forever.
TEST_F(ClipRange, AnAnimatedWebpOfOneShotsPlaysEachDirectionOnce) {
  ASSERT_FALSE(bar().empty());
  auto c = client();
  const json bend_once = {{"clip", "Bend"}, {"frames", 5}, {"range", {0.25, 0.75}}, {"loop", false}};
  json params = {{"model", bar()},
                 {"width", 32},
                 {"height", 32},
                 {"background", {0, 0, 0, 0}},
                 {"sheet", {{"frames", 2}, {"animate", true}, {"animation", bend_once}}}};
  const auto res = post_json(c, "/render", params);
  ASSERT_TRUE(res && res->status == 200) << (res ? res->body : "no answer");
  const WebpFrames webp = decode_webp_frames(res->body);
  EXPECT_EQ(webp.loop_count, 1);
  // 5 frames 125 ms apart per direction, the last pose's for a step too.
  const std::vector<int> ends = {125, 250, 375, 500, 625, 750, 875, 1000, 1125, 1250};
  EXPECT_EQ(webp.end_ms, ends);
  // Frame by frame the sheet's tiles, in the atlas's order: the first
  // direction from the range's start to its end, then the second.
  params["sheet"]["animate"] = false;
  const json atlas = atlas_of(params);
  const std::vector<image::Image> tiles = sheet_tiles(sheet_of(params), atlas);
  ASSERT_EQ(webp.frames.size(), tiles.size());
  for (std::size_t i = 0; i < tiles.size(); ++i) EXPECT_EQ(webp.frames[i].rgba, tiles[i].rgba) << "frame " << i;
  EXPECT_DOUBLE_EQ(atlas["frames"]["4"]["time"].get<double>(), 0.75);
  EXPECT_DOUBLE_EQ(atlas["frames"]["5"]["time"].get<double>(), 0.25);

  params["sheet"]["animate"] = true;
  params["sheet"]["animation"] = {bend_once, {{"clip", "Twist"}, {"frames", 3}}};
  const auto mixed = post_json(c, "/render", params);
  ASSERT_TRUE(mixed && mixed->status == 200) << (mixed ? mixed->body : "no answer");
  EXPECT_EQ(decode_webp_frames(mixed->body).loop_count, 0);
}

// ---- errors ----------------------------------------------------------------------

// A range outside the clip, one that ends where it starts or before, and a
// range on a model without clips: 422 naming the range's field.
TEST_F(ClipRange, BadRangesAreRefusedAtTheirField) {
  ASSERT_FALSE(bar().empty());
  auto c = client();
  const auto answer = [&](const json& params) {
    const auto res = post_json(c, "/render", params);
    return std::pair{res ? res->status : 0, res && res->status != 200 ? error_of(res) : json::object()};
  };
  const auto single = [&](const std::string& model, const json& range) {
    json params = {{"width", 32}, {"height", 32}, {"animation", {{"clip", "Bend"}, {"range", range}}}};
    if (!model.empty()) params["model"] = model;
    return answer(params);
  };
  const auto in_sheet = [&](const std::string& model, const json& clips) {
    json params = {{"width", 32}, {"height", 32}, {"sheet", {{"frames", 1}, {"animation", clips}}}};
    if (!model.empty()) params["model"] = model;
    return answer(params);
  };
  // Bend runs from 0 to 1 s.
  for (const json& range : {json{0.5, 1.5}, json{-0.25, 0.5}, json{1.25, 2.0}, json{0.5, 0.5}, json{0.75, 0.25}}) {
    const auto [status, error] = single(bar(), range);
    EXPECT_EQ(status, 422) << range;
    EXPECT_EQ(error["code"], "bad_range") << range;
    EXPECT_EQ(error["path"], "/animation/range") << range << ": " << error;
    const auto [sheet_status, sheet_error] = in_sheet(bar(), {{"clip", "Bend"}, {"range", range}});
    EXPECT_EQ(sheet_status, 422) << range;
    EXPECT_EQ(sheet_error["path"], "/sheet/animation/range") << range << ": " << sheet_error;
    const auto [list_status, list_error] =
        in_sheet(bar(), {{{"clip", "Twist"}}, {{"clip", "Bend"}, {"range", range}, {"loop", false}}});
    EXPECT_EQ(list_status, 422) << range;
    EXPECT_EQ(list_error["path"], "/sheet/animation/1/range") << range << ": " << list_error;
  }
  const auto [past_status, past] = single(bar(), {0.5, 1.5});
  EXPECT_NE(past["message"].get<std::string>().find("runs from 0 to 1 s"), std::string::npos) << past;
  const auto [empty_status, empty] = single(bar(), {0.75, 0.25});
  EXPECT_NE(empty["message"].get<std::string>().find("the end must be later"), std::string::npos) << empty;
  // Figures rounded at the end are the end.
  EXPECT_EQ(single(bar(), {0.5, 1.0004}).first, 200);
  EXPECT_EQ(single(bar(), {0.0, 1.0}).first, 200);
  // The demo model has no clips: the range is what cannot be.
  const auto [demo_status, demo] = single("", {0.0, 0.5});
  EXPECT_EQ(demo_status, 422);
  EXPECT_EQ(demo["path"], "/animation/range") << demo;
  EXPECT_NE(demo["message"].get<std::string>().find("no animation clips"), std::string::npos) << demo;
  EXPECT_EQ(in_sheet("", {{"clip", 0}, {"range", {0.0, 0.5}}}).second["path"], "/sheet/animation/range");
  EXPECT_EQ(in_sheet("", {{{"clip", 0}}, {{"clip", 0}, {"range", {0.0, 0.5}}}}).second["path"],
            "/sheet/animation/0/clip")
      << "the first entry, without a range, is refused first, at its clip";
}

// The CLI as users type it: a range as two numbers, into a sheet's clip.
TEST_F(ClipRange, TheCliTakesARangeInSecondsOrInFrames) {
  const RangeModel& b3d = minetest();
  ASSERT_FALSE(b3d.id.empty());
  const auto dir = make_temp_dir("toon-range");
  const json range = walk_range(60.0);
  const json request = sheet_request(b3d.id, {{"clip", "anim"}, {"frames", 2}, {"range", range}, {"loop", false}});
  const image::Image expected = sheet_of(request);
  const auto render = [&](const std::string& range_text, const std::string& png) {
    return run_process({TOON_BINARY, "render",
                        "--model",   b3d.id,
                        "--set",     "width=96",
                        "--set",     "height=96",
                        "--set",     "background=[0,0,0,0]",
                        "--set",     "sheet.frames=4",
                        "--set",     "sheet.yaw_start=0",
                        "--set",     "sheet.animation.clip=anim",
                        "--set",     "sheet.animation.frames=2",
                        "--set",     "sheet.animation.loop=false",
                        "--set",     "sheet.animation.range=" + range_text,
                        "-o",        (dir / png).string(),
                        "--server",  daemon().url()});
  };
  char seconds[64];
  std::snprintf(seconds, sizeof seconds, "%.17g,%.17g", range[0].get<double>(), range[1].get<double>());
  const auto in_seconds = render(seconds, "seconds.png");
  ASSERT_EQ(in_seconds.status, 0) << in_seconds.err;
  EXPECT_EQ(image::decode_png(read_file(dir / "seconds.png")).rgba, expected.rgba);
  const auto in_frames = render("168f,187f", "frames.png");
  ASSERT_EQ(in_frames.status, 0) << in_frames.err;
  EXPECT_EQ(image::decode_png(read_file(dir / "frames.png")).rgba, expected.rgba);
  // glTF keys by seconds: no frames to count.
  ASSERT_FALSE(blender_twin().id.empty());
  const auto gltf =
      run_process({TOON_BINARY, "render", "--model", blender_twin().id, "--set", "animation.clip=0", "--set",
                   "animation.range=168f,187f", "-o", (dir / "gltf.png").string(), "--server", daemon().url()});
  EXPECT_EQ(gltf.status, 2);
  EXPECT_NE(gltf.err.find("frame rate"), std::string::npos) << gltf.err;
}

}  // namespace
}  // namespace toond::test
