// A rigged, animated glTF from a real exporter (Blender's bending bar:
// tests/exported/blender/make_rigged.py) posed through the default request
// with `animation`: what the upload says of it, frames of a clip framed
// alike and never cut off, time wrapping, every output layer following the
// pose, the errors, and the CLI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "image/png_codec.h"
#include "support/edge_measure.h"
#include "support/golden_compare.h"
#include "support/shared_models.h"
#include "support/webp_frames.h"
#include "test_client.h"

namespace toond::test {
namespace {

using json = nlohmann::json;

// The daemon poses in the vertex stage, as on a GPU (on llvmpipe its
// default is the CPU, which the other suites' daemons use).
class AnimatedModel : public SharedDaemonTest {
 public:
  static void SetUpTestSuite() {
    daemon_ = std::make_unique<Daemon>(std::filesystem::path{}, std::vector<std::string>{"--skinning", "gpu"});
  }

 protected:
  static httplib::Client daemon_client() { return daemon().client(); }
  // The atlas alone (?atlas=json) of a sheet request that must succeed.
  static json sheet_atlas(const json& params) {
    auto client = daemon_client();
    const auto res = post_json(client, "/render?atlas=json", params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << (res ? std::to_string(res->status) + ": " + res->body : "no answer");
      return json::object();
    }
    return json::parse(res->body);
  }

  static json upload() {
    auto client = daemon().client();
    const auto res = upload_files(client, TOOND_EXPORTED_DIR "/blender", {"rigged.gltf", "rigged.bin"});
    if (!res || (res->status != 200 && res->status != 201)) {
      ADD_FAILURE() << (res ? res->body : "no answer");
      return json::object();
    }
    return json::parse(res->body);
  }
  static std::string id() {
    static const std::string model = upload().value("id", "");
    return model;
  }
  static image::Image pose(double time, const std::string& output = "color", const json& clip = "Bend") {
    auto client = daemon().client();
    return render_ok(client, {{"model", id()},
                              {"width", 96},
                              {"height", 96},
                              {"output", output},
                              {"animation", {{"clip", clip}, {"time", time}}}});
  }
};

// Blender's walking character (tests/exported/blender/make_walker.py): a
// Walk and an Idle clip.
std::string upload_walker(httplib::Client& client) {
  const auto uploaded = upload_files(client, TOOND_EXPORTED_DIR "/blender", {"walker.glb"});
  if (!uploaded || (uploaded->status != 200 && uploaded->status != 201)) {
    ADD_FAILURE() << (uploaded ? uploaded->body : "no answer");
    return {};
  }
  return json::parse(uploaded->body)["id"];
}

// A sheet of the walker's Walk: `directions` rows from yaw 0 of `frames`
// frames each, 96² tiles on a transparent background.
json walk_sheet(const std::string& walker, const json& camera, int directions, int frames) {
  return {{"model", walker},
          {"width", 96},
          {"height", 96},
          {"background", {0, 0, 0, 0}},
          {"camera", camera},
          {"sheet", {{"frames", directions}, {"yaw_start", 0}, {"animation", {{"clip", "Walk"}, {"frames", frames}}}}}};
}

// The PNG of a sheet request that must succeed, decoded.
image::Image rendered_sheet(httplib::Client& client, const json& params) {
  const auto res = post_json(client, "/render", params);
  if (!res || res->status != 200) {
    ADD_FAILURE() << (res ? std::to_string(res->status) + ": " + res->body : "no answer");
    return {};
  }
  return image::decode_png(res->body);
}

// Pixels that are not the background (alpha or colour differs from the
// corner pixel's).
std::vector<bool> drawn(const image::Image& img) {
  std::vector<bool> mask(img.rgba.size() / 4);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    for (std::size_t k = 0; k < 4; ++k) mask[i] = mask[i] || img.rgba[4 * i + k] != img.rgba[k];
  }
  return mask;
}

TEST_F(AnimatedModel, TheUploadListsClipsJointsAndMorphTargets) {
  const json info = upload();
  ASSERT_TRUE(info.contains("animation")) << info.dump();
  const json& a = info["animation"];
  ASSERT_EQ(a["clips"].size(), 2u);
  EXPECT_EQ(a["clips"][0]["name"], "Bend");
  EXPECT_DOUBLE_EQ(a["clips"][0]["duration"].get<double>(), 1.0);
  EXPECT_EQ(a["clips"][0]["channels"], 10);
  EXPECT_EQ(a["clips"][1]["name"], "Twist");
  EXPECT_DOUBLE_EQ(a["clips"][1]["duration"].get<double>(), 0.5);
  EXPECT_FALSE(a["clips"][0].contains("frame_rate"));  // glTF keys by seconds
  EXPECT_EQ(a["joints"], 3);
  EXPECT_EQ(a["morph_targets"], 1);
  for (const json& warning : info["warnings"]) {
    EXPECT_EQ(warning.get<std::string>().find("animations"), std::string::npos) << warning;
    EXPECT_EQ(warning.get<std::string>().find("skins"), std::string::npos) << warning;
  }
  auto client = daemon().client();
  const auto again = client.Get(("/models/" + id()).c_str());
  ASSERT_TRUE(again && again->status == 200);
  EXPECT_EQ(json::parse(again->body)["animation"], a);
}

// Minetest's own player (tests/exported/minetest), as a new user uploads
// it: the B3D with the skin the game gives it. Its clip runs one key past
// the length the file states, which is said, not refused; the clip lists
// the file's frame rate, and the walk (frames 168-187) moves it.
TEST_F(AnimatedModel, MinetestsPlayerUploadsWithItsSkinAndItsClipsFrameRate) {
  auto client = daemon_client();
  const auto res = upload_files(client, TOOND_EXPORTED_DIR "/minetest", {"character.b3d", "character.png"});
  ASSERT_TRUE(res && (res->status == 201 || res->status == 200)) << (res ? res->body : "no answer");
  const json info = json::parse(res->body);
  EXPECT_EQ(info["textures"], 1);
  ASSERT_EQ(info["animation"]["clips"].size(), 1u) << info.dump();
  const json& clip = info["animation"]["clips"][0];
  EXPECT_EQ(clip["frame_rate"], 60.0);
  EXPECT_NEAR(clip["duration"].get<double>(), 220.0 / 60.0, 1e-6);
  EXPECT_NE(info["warnings"].dump().find("past the 220 its file states"), std::string::npos) << info["warnings"];
  const std::string id = info["id"];
  const auto again = client.Get(("/models/" + id).c_str());
  ASSERT_TRUE(again && again->status == 200);
  EXPECT_EQ(json::parse(again->body)["animation"], info["animation"]);
  const auto at_frame = [&](int frame) {
    return render_ok(
        client, {{"model", id}, {"width", 96}, {"height", 96}, {"animation", {{"clip", 0}, {"time", frame / 60.0}}}});
  };
  const image::Image standing = at_frame(0), walking = at_frame(173);
  EXPECT_NE(standing.rgba, walking.rgba);
  const std::vector<bool> walker = drawn(walking);
  EXPECT_GT(std::count(walker.begin(), walker.end(), true), 500);
}

TEST_F(AnimatedModel, ServerTimingCountsThePosing) {
  auto client = daemon_client();
  const auto posed =
      post_json(client, "/render",
                {{"model", id()}, {"width", 32}, {"height", 32}, {"animation", {{"clip", "Bend"}, {"time", 0.3}}}});
  ASSERT_TRUE(posed && posed->status == 200);
  const std::string timing = posed->get_header_value("Server-Timing");
  EXPECT_EQ(timing.rfind("pose;dur=", 0), 0u) << timing;
  const auto rest = post_json(client, "/render", {{"model", id()}, {"width", 32}, {"height", 32}});
  EXPECT_EQ(rest->get_header_value("Server-Timing").find("pose;"), std::string::npos);
}

TEST_F(AnimatedModel, APoseDiffersFromTheRestAndTimeWrapsRoundTheLoop) {
  const image::Image start = pose(0.0);
  const image::Image quarter = pose(0.25);
  EXPECT_NE(start.rgba, quarter.rgba);
  EXPECT_EQ(pose(1.0).rgba, start.rgba);                 // the clip's duration is its start again
  EXPECT_EQ(pose(1.25).rgba, quarter.rgba);              // past the end: round again
  EXPECT_EQ(pose(-0.75).rgba, quarter.rgba);             // before the start: back from the end
  EXPECT_EQ(pose(0.25, "color", 0).rgba, quarter.rgba);  // the clip by its index
}

TEST_F(AnimatedModel, NoFrameOfAClipIsCutOff) {
  // Frame by frame at 24 per second, every frame framed by the whole clip:
  // nothing touches the image's edge. (That the framing is one for all
  // frames is checked by the sheet tests: tiles equal single renders, and
  // the walker's feet stay put.)
  int frames = 0;
  for (int k = 0; k < 24; ++k) {
    const image::Image img = pose(k / 24.0);
    const std::vector<bool> mask = drawn(img);
    for (int i = 0; i < img.width; ++i) {
      for (const int edge : {0, img.height - 1}) {
        EXPECT_FALSE(mask[static_cast<std::size_t>(edge * img.width + i)]) << "frame " << k;
        EXPECT_FALSE(mask[static_cast<std::size_t>(i * img.width + edge)]) << "frame " << k;
      }
    }
    ++frames;
  }
  EXPECT_EQ(frames, 24);
}

TEST_F(AnimatedModel, EveryOutputLayerFollowsThePose) {
  const std::vector<bool> colour = drawn(pose(0.5));
  for (const std::string output : {"normal", "depth", "id", "lines"}) {
    const std::vector<bool> layer = drawn(pose(0.5, output));
    const std::vector<bool> rest = drawn(pose(0.0, output));
    std::size_t outside = 0, moved = 0;
    for (std::size_t i = 0; i < layer.size(); ++i) {
      // The colour image's outline is wider than any layer's edge.
      outside += layer[i] && !colour[i];
      moved += layer[i] != rest[i];
    }
    EXPECT_EQ(outside, 0u) << output << ": pixels drawn outside the posed model";
    EXPECT_GT(moved, 200u) << output << " did not move with the pose";
  }
}

TEST_F(AnimatedModel, AnUnknownClipNamesTheClipsThereAre) {
  auto client = daemon().client();
  const auto res = post_json(client, "/render", {{"model", id()}, {"animation", {{"clip", "Walk"}}}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422);
  const json error = error_of(res);
  EXPECT_EQ(error["path"], "/animation/clip");
  EXPECT_NE(error["message"].get<std::string>().find("\"Bend\", \"Twist\""), std::string::npos) << error;
  const auto past = post_json(client, "/render", {{"model", id()}, {"animation", {{"clip", 2}}}});
  EXPECT_EQ(past->status, 422);
  EXPECT_EQ(error_of(past)["path"], "/animation/clip");
}

TEST_F(AnimatedModel, AModelWithoutClipsOrAScenesObjectsCannotBeAnimated) {
  auto client = daemon().client();
  const auto demo = post_json(client, "/render", {{"animation", {{"clip", "Bend"}}}});
  EXPECT_EQ(demo->status, 422);
  EXPECT_NE(error_of(demo)["message"].get<std::string>().find("has no animation clips"), std::string::npos);
  const auto scene =
      post_json(client, "/render", {{"objects", {{{"model", id()}}}}, {"animation", {{"clip", "Bend"}}}});
  EXPECT_EQ(scene->status, 400);
  EXPECT_EQ(error_of(scene)["path"], "/animation");
  const auto no_clip = post_json(client, "/render", {{"model", id()}, {"animation", {{"time", 0.5}}}});
  EXPECT_EQ(no_clip->status, 400);
}

TEST_F(AnimatedModel, TheCliListsTheClipsAndRendersAPose) {
  const auto dir = make_temp_dir("toon-animation");
  const auto info = run_process({TOON_BINARY, "info", id(), "--server", daemon().url()});
  EXPECT_EQ(info.status, 0) << info.err;
  EXPECT_NE(info.out.find("\"Twist\""), std::string::npos) << info.out;
  const auto png = dir / "bend.png";
  const auto render = run_process({TOON_BINARY, "render", "--model", id(), "--set", "width=96", "--set", "height=96",
                                   "--set", "animation.clip=Bend", "--set", "animation.time=0.25", "-o", png.string(),
                                   "--server", daemon().url()});
  ASSERT_EQ(render.status, 0) << render.err;
  EXPECT_EQ(image::decode_png(read_file(png)).rgba, pose(0.25).rgba);
}

// The same walk drawn by a daemon that poses on the CPU: the same pixels,
// single frames and a sheet alike.
TEST_F(AnimatedModel, PosingOnTheCpuDrawsWhatTheVertexStageDraws) {
  Daemon on_cpu({}, {"--skinning", "cpu"});
  const auto upload_walker = [](const Daemon& d) {
    auto client = d.client();
    const auto res = upload_files(client, TOOND_EXPORTED_DIR "/blender", {"walker.glb"});
    return res && (res->status == 200 || res->status == 201) ? json::parse(res->body).value("id", "") : "";
  };
  const std::string in_vertex_stage_id = upload_walker(daemon());
  const std::string on_cpu_id = upload_walker(on_cpu);
  ASSERT_FALSE(in_vertex_stage_id.empty());
  ASSERT_EQ(on_cpu_id, in_vertex_stage_id);
  const json requests[] = {
      {{"width", 128}, {"height", 128}, {"animation", {{"clip", "Walk"}, {"time", 0.3}}}},
      {{"width", 128}, {"height", 128}, {"output", "normal"}, {"animation", {{"clip", "Walk"}, {"time", 0.7}}}},
      {{"width", 256}, {"height", 128}, {"sheet", {{"frames", 2}, {"animation", {{"clip", "Walk"}, {"frames", 2}}}}}},
  };
  for (json request : requests) {
    request["model"] = on_cpu_id;
    auto gpu_client = daemon().client();
    auto cpu_client = on_cpu.client();
    const image::Image a = render_ok(gpu_client, request);
    const image::Image b = render_ok(cpu_client, request);
    ASSERT_EQ(a.rgba.size(), b.rgba.size()) << request.dump();
    int differing = 0;
    for (std::size_t k = 0; k < a.rgba.size(); k += 4) {
      for (std::size_t c = 0; c < 4; ++c) {
        if (std::abs(a.rgba[k + c] - b.rgba[k + c]) > 8) {
          ++differing;
          break;
        }
      }
    }
    EXPECT_LE(differing, 4) << request.dump();
  }
  // Posing on the CPU is counted where it happens, on the render thread.
  auto client = on_cpu.client();
  const auto posed = post_json(
      client, "/render",
      {{"model", on_cpu_id}, {"width", 32}, {"height", 32}, {"animation", {{"clip", "Walk"}, {"time", 0.1}}}});
  ASSERT_TRUE(posed && posed->status == 200);
  EXPECT_NE(posed->get_header_value("Server-Timing").find(", pose_vertices;dur="), std::string::npos)
      << posed->get_header_value("Server-Timing");
  auto gpu_client = daemon().client();
  const auto skinned = post_json(
      gpu_client, "/render",
      {{"model", on_cpu_id}, {"width", 32}, {"height", 32}, {"animation", {{"clip", "Walk"}, {"time", 0.1}}}});
  ASSERT_TRUE(skinned && skinned->status == 200);
  EXPECT_EQ(skinned->get_header_value("Server-Timing").find("pose_vertices"), std::string::npos);
}

// glTF ignores a skinned mesh's own node transform: Blender's bar with its
// mesh node squashed to half height is drawn at rest where its joints put
// it, the unsquashed bar's very faces, single image and sheet alike. Only
// the outline ring may differ by a pixel: its mitred offsets, made at
// import from the squashed faces, do not turn back exactly under a
// non-uniform scale.
TEST_F(AnimatedModel, TheRestPoseIsWhereTheJointsPutTheSkin) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  json gltf = json::parse(read_file(folder / "rigged.gltf"));
  gltf["nodes"][3]["scale"] = {1.0, 0.5, 1.0};
  auto client = daemon_client();
  httplib::MultipartFormDataItems items = {
      {"file", gltf.dump(), "rigged.gltf", "model/gltf+json"},
      {"file", read_file(folder / "rigged.bin"), "rigged.bin", "application/octet-stream"}};
  const auto res = client.Post("/models", items);
  ASSERT_TRUE(res && (res->status == 200 || res->status == 201)) << (res ? res->body : "no answer");
  const std::string squashed = json::parse(res->body)["id"];
  const json requests[] = {
      {{"width", 96}, {"height", 96}, {"outline", {{"enabled", false}}}},
      {{"width", 96}, {"height", 96}},
      {{"width", 192}, {"height", 96}, {"sheet", {{"frames", 2}}}},
  };
  // Whether a line pixel (dark) lies within one pixel of (x, y) in `img`.
  const auto by_a_line = [](const image::Image& img, int x, int y) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= img.width || ny >= img.height) continue;
        const std::uint8_t* p = img.pixel(nx, ny);
        if (p[3] > 0 && std::max({p[0], p[1], p[2]}) < 60) return true;
      }
    }
    return false;
  };
  for (const json& request : requests) {
    json plain_request = request, squashed_request = request;
    plain_request["model"] = id();
    squashed_request["model"] = squashed;
    const image::Image plain = render_ok(client, plain_request);
    const image::Image at_rest = render_ok(client, squashed_request);
    ASSERT_EQ(plain.rgba.size(), at_rest.rgba.size());
    int differing = 0, off_the_lines = 0;
    for (int y = 0; y < plain.height; ++y) {
      for (int x = 0; x < plain.width; ++x) {
        bool differs = false;
        for (std::size_t c = 0; c < 4; ++c) differs |= std::abs(plain.pixel(x, y)[c] - at_rest.pixel(x, y)[c]) > 8;
        differing += differs;
        off_the_lines += differs && !by_a_line(plain, x, y) && !by_a_line(at_rest, x, y);
      }
    }
    std::printf("squashed skin at rest, %s: %d pixels differ, %d of them off the lines\n", request.dump().c_str(),
                differing, off_the_lines);
    EXPECT_LE(off_the_lines, 4) << request.dump();
    if (request.contains("outline")) {
      EXPECT_LE(differing, 4) << request.dump();
    }
  }
}

// ---- animated sheets -------------------------------------------------------

TEST_F(AnimatedModel, AnAnimatedSheetHasARowPerDirectionAndAColumnPerFrame) {
  const json sheet = {{"frames", 4},
                      {"animation", {{{"clip", "Bend"}, {"frames", 8}}, {{"clip", "Twist"}, {"fps", 12}}}}};
  const json params = {{"model", id()}, {"width", 48}, {"height", 48}, {"sheet", sheet}};
  const json atlas = sheet_atlas(params);
  // Bend: 4 rows of 8 frames; Twist (0.5 s at 12 fps): 4 rows of 6.
  ASSERT_EQ(atlas["frames"].size(), 4u * 8u + 4u * 6u);
  EXPECT_EQ(atlas["meta"]["size"], json({{"w", 8 * 48}, {"h", 8 * 48}}));
  const json& f9 = atlas["frames"]["9"];  // Bend, second direction, second frame
  EXPECT_EQ(f9["clip"], "Bend");
  EXPECT_DOUBLE_EQ(f9["time"].get<double>(), 0.125);
  EXPECT_EQ(f9["duration"], 125);
  EXPECT_EQ(f9["frame"]["x"], 48);
  EXPECT_EQ(f9["frame"]["y"], 48);
  const json& twist = atlas["frames"]["33"];  // Twist, first direction, second frame
  EXPECT_EQ(twist["clip"], "Twist");
  EXPECT_NEAR(twist["time"].get<double>(), 0.5 / 6, 1e-12);
  // Whole milliseconds, as engines play them: 83 and 84 in turn, 500 a row.
  EXPECT_EQ(twist["duration"], 84);
  int twist_row_ms = 0;
  for (int i = 32; i < 38; ++i) twist_row_ms += atlas["frames"][std::to_string(i)]["duration"].get<int>();
  EXPECT_EQ(twist_row_ms, 500);
  EXPECT_EQ(twist["frame"]["y"], 4 * 48);
  // Aseprite tags: one per clip and direction, over its row.
  const json& tags = atlas["meta"]["frameTags"];
  ASSERT_EQ(tags.size(), 8u);
  // Directions from the camera's default yaw (30°) a quarter turn apart.
  EXPECT_EQ(tags[0]["name"], "Bend_30");
  EXPECT_EQ(tags[1]["name"], "Bend_120");
  EXPECT_DOUBLE_EQ(tags[1]["yaw"].get<double>(), 120.0);
  EXPECT_EQ(tags[1]["from"], 8);
  EXPECT_EQ(tags[1]["to"], 15);
  EXPECT_EQ(tags[1]["direction"], "forward");
  EXPECT_EQ(tags[4]["clip"], "Twist");
  EXPECT_EQ(tags[4]["name"], "Twist_30");
  EXPECT_EQ(tags[4]["from"], 32);
  EXPECT_EQ(tags[4]["to"], 37);
  // PixiJS plays the top-level animations: a tag's frames by name.
  ASSERT_EQ(atlas["animations"].size(), 8u);
  EXPECT_EQ(atlas["animations"]["Twist_30"], json({"32", "33", "34", "35", "36", "37"}));
}

TEST_F(AnimatedModel, EachTileOfAnAnimatedSheetIsTheSingleRenderOfItsPoseAndView) {
  const json params = {{"model", id()},
                       {"width", 64},
                       {"height", 64},
                       {"sheet", {{"frames", 3}, {"animation", {{"clip", "Bend"}, {"frames", 4}}}}}};
  auto client = daemon_client();
  const auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res && res->status == 200) << (res ? res->body : "");
  const image::Image sheet = image::decode_png(res->body);
  const json atlas = sheet_atlas(params);
  const double distance = atlas["meta"]["camera"]["distance"];
  ASSERT_EQ(atlas["frames"].size(), 12u);
  // The sheet's light turns with its camera: the single render's does too.
  const json view_light = {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}, {"space", "view"}}};
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const image::Image single =
        render_ok(client, {{"model", id()},
                           {"width", 64},
                           {"height", 64},
                           {"camera", {{"yaw", frame["yaw"]}, {"pitch", frame["pitch"]}, {"distance", distance}}},
                           {"lights", view_light},
                           {"animation", {{"clip", frame["clip"]}, {"time", frame["time"]}}}});
    const GoldenDiff diff = compare_golden(single, tile_of(sheet, frame["frame"]));
    EXPECT_TRUE(diff.passes()) << name << ": " << diff.pixels_over << " pixels differ, largest " << diff.largest;
  }
}

// The walk in a dimetric (orthographic) sheet, 4 directions × 6 frames:
// each tile, the yaw-0 ones too, is the single render of its pose and view
// with the sheet's view-space light at meta.camera.distance, which in an
// orthographic view sizes it. (Before that, a single render there fitted
// its own view alone, and only the direction whose fit the sheet's was
// came out the same: 9-18 % of the pixels of the other three differed.)
TEST_F(AnimatedModel, EachTileOfADimetricWalkIsTheSingleRenderOfItsPoseAndView) {
  auto client = daemon_client();
  const std::string walker = upload_walker(client);
  ASSERT_FALSE(walker.empty());
  const json params = walk_sheet(walker, {{"preset", "dimetric"}}, 4, 6);
  const image::Image sheet = rendered_sheet(client, params);
  ASSERT_GT(sheet.width, 0);
  const json atlas = sheet_atlas(params);
  ASSERT_EQ(atlas["frames"].size(), 24u);
  const double distance = atlas["meta"]["camera"]["distance"];
  const json view_light = {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}, {"space", "view"}}};
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const image::Image single = render_ok(
        client,
        {{"model", walker},
         {"width", 96},
         {"height", 96},
         {"background", {0, 0, 0, 0}},
         {"camera", {{"preset", "dimetric"}, {"yaw", frame["yaw"]}, {"pitch", frame["pitch"]}, {"distance", distance}}},
         {"lights", view_light},
         {"animation", {{"clip", frame["clip"]}, {"time", frame["time"]}}}});
    const GoldenDiff diff = compare_golden(single, tile_of(sheet, frame["frame"]));
    EXPECT_TRUE(diff.passes()) << name << " (yaw " << frame["yaw"] << "): " << diff.pixels_over
                               << " pixels differ, largest " << diff.largest;
  }
}

// The median relative luminance (linear light) of a row's fully covered
// pixels, per yaw.
std::map<double, double> median_luminance_by_yaw(const image::Image& sheet, const json& atlas) {
  if (sheet.width == 0) return {};
  std::map<double, std::vector<double>> values;
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const image::Image tile = tile_of(sheet, frame["frame"]);
    std::vector<double>& row = values[frame["yaw"].get<double>()];
    for (int y = 0; y < tile.height; ++y) {
      for (int x = 0; x < tile.width; ++x) {
        const std::uint8_t* p = tile.pixel(x, y);
        if (p[3] != 255) continue;
        row.push_back(0.2126 * srgb_byte_to_linear(p[0]) + 0.7152 * srgb_byte_to_linear(p[1]) +
                      0.0722 * srgb_byte_to_linear(p[2]));
      }
    }
  }
  std::map<double, double> medians;
  for (auto& [yaw, row] : values) {
    std::nth_element(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(row.size() / 2), row.end());
    medians[yaw] = row.empty() ? 0.0 : row[row.size() / 2];
  }
  return medians;
}

// A sheet's directions are lit alike: the character turns under the
// light, as it does in a game. Seen from behind (yaw 180) the walker is
// lit like its front (yaw 0): its median luminance at least 80 % of the
// front's. With the light kept in the model's space, the back is in the
// model's own shade.
TEST_F(AnimatedModel, ASheetLightsTheBackViewLikeTheFront) {
  auto client = daemon_client();
  const std::string walker = upload_walker(client);
  ASSERT_FALSE(walker.empty());
  for (const json& camera : {json::object(), json{{"preset", "dimetric"}}}) {
    json params = walk_sheet(walker, camera, 4, 6);
    const std::map<double, double> by_default =
        median_luminance_by_yaw(rendered_sheet(client, params), sheet_atlas(params));
    ASSERT_TRUE(by_default.contains(0.0) && by_default.contains(180.0));
    EXPECT_GE(by_default.at(180.0), 0.8 * by_default.at(0.0))
        << camera.dump() << ": back " << by_default.at(180.0) << ", front " << by_default.at(0.0);

    params["lights"] = {{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}, {"space", "model"}}};
    const std::map<double, double> in_model =
        median_luminance_by_yaw(rendered_sheet(client, params), sheet_atlas(params));
    ASSERT_TRUE(in_model.contains(0.0) && in_model.contains(180.0));
    EXPECT_LT(in_model.at(180.0), 0.8 * in_model.at(0.0))
        << camera.dump() << ": a model-space light leaves the back darker (back " << in_model.at(180.0) << ", front "
        << in_model.at(0.0) << ")";
    std::printf("camera %s: back / front median luminance %.3f by default (view), %.3f with the light in model space\n",
                camera.dump().c_str(), by_default.at(180.0) / by_default.at(0.0),
                in_model.at(180.0) / in_model.at(0.0));
  }
}

TEST_F(AnimatedModel, AnAnimatedWebpPlaysTheClipsWithTheirOwnFrameTimes) {
  // Twist lasts 0.5 s: 6 frames at 12 per second end at 83, 167, 250, ...
  // ms of each direction's loop (rounded as the exact times add up).
  const json params = {{"model", id()},
                       {"width", 32},
                       {"height", 32},
                       {"sheet", {{"frames", 2}, {"animate", true}, {"animation", {{"clip", "Twist"}, {"fps", 12}}}}}};
  auto client = daemon_client();
  const auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res && res->status == 200) << (res ? res->body : "");
  EXPECT_EQ(res->get_header_value("Content-Type"), "image/webp");
  const WebpFrames webp = decode_webp_frames(res->body);
  ASSERT_EQ(webp.end_ms.size(), 12u);
  const std::vector<int> expected = {83, 167, 250, 333, 417, 500, 583, 667, 750, 833, 917, 1000};
  EXPECT_EQ(webp.end_ms, expected);
}

TEST_F(AnimatedModel, ANormalLayerSheetOfAClipMatchesItsColourSheetFrameForFrame) {
  // Dynamic 2D lighting takes a normal-map sheet beside the colour sheet:
  // the same tiles, the same poses, the model covering the same pixels.
  json params = {{"model", id()},
                 {"width", 48},
                 {"height", 48},
                 {"background", {0, 0, 0, 0}},
                 {"outline", {{"enabled", false}}},
                 {"sheet", {{"frames", 2}, {"animation", {{"clip", "Bend"}, {"frames", 4}}}}}};
  auto client = daemon_client();
  const auto colour = post_json(client, "/render", params);
  params["output"] = "normal";
  const auto normal = post_json(client, "/render", params);
  ASSERT_TRUE(colour && colour->status == 200 && normal && normal->status == 200);
  const image::Image c = image::decode_png(colour->body), n = image::decode_png(normal->body);
  ASSERT_EQ(c.width, n.width);
  ASSERT_EQ(c.height, n.height);
  // Pixels the colour sheet covers fully must hold a normal, pixels it
  // leaves empty none (edge pixels, partly covered, may go either way).
  std::size_t differ = 0, covered = 0;
  for (std::size_t i = 3; i < c.rgba.size(); i += 4) {
    covered += c.rgba[i] == 255;
    differ += (c.rgba[i] == 255 && n.rgba[i] == 0) || (c.rgba[i] == 0 && n.rgba[i] > 0);
  }
  EXPECT_GT(covered, 500u);
  EXPECT_EQ(differ, 0u) << differ << " pixels are covered in one sheet and empty in the other";
}

// Blender's walking character (tests/exported/blender/make_walker.py):
// its Walk cycle has no root motion and a foot on the ground at every
// frame, so in a sheet seen level (orthographic, pitch 0: the ground is one
// row of pixels, however near or far a foot is) the lowest covered pixel
// row of each direction's frames stays where it is, within a pixel.
TEST_F(AnimatedModel, AWalkingCharactersFeetStayPutInEveryDirection) {
  auto client = daemon_client();
  const std::string walker = upload_walker(client);
  ASSERT_FALSE(walker.empty());
  const json params = walk_sheet(walker, {{"projection", "orthographic"}, {"pitch", 0}}, 8, 12);
  const image::Image sheet = rendered_sheet(client, params);
  ASSERT_GT(sheet.width, 0);
  const json atlas = sheet_atlas(params);
  ASSERT_EQ(atlas["frames"].size(), 96u);
  std::map<double, std::pair<int, int>> lowest_by_yaw;  // yaw → (min, max) of the lowest covered row
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const image::Image tile = tile_of(sheet, frame["frame"]);
    int lowest = -1;
    for (int y = 0; y < tile.height; ++y) {
      for (int x = 0; x < tile.width; ++x) {
        if (tile.rgba[(static_cast<std::size_t>(y) * tile.width + x) * 4 + 3] > 0) lowest = y;
      }
    }
    ASSERT_GE(lowest, 0) << name << " is empty";
    auto [it, added] = lowest_by_yaw.try_emplace(frame["yaw"].get<double>(), lowest, lowest);
    it->second = {std::min(it->second.first, lowest), std::max(it->second.second, lowest)};
  }
  ASSERT_EQ(lowest_by_yaw.size(), 8u);
  for (const auto& [yaw, range] : lowest_by_yaw) {
    EXPECT_LE(range.second - range.first, 1)
        << "yaw " << yaw << ": the lowest row goes from " << range.first << " to " << range.second;
  }
}

TEST_F(AnimatedModel, AnAnimatedSheetRefusesWhatCannotBe) {
  auto client = daemon_client();
  const auto code_and_path = [&](const json& sheet, const json& extra = json::object()) {
    json params = {{"model", id()}, {"width", 32}, {"height", 32}, {"sheet", sheet}};
    params.update(extra);
    const auto res = post_json(client, "/render", params);
    return std::pair{res ? res->status : 0, res ? error_of(res)["path"].get<std::string>() : ""};
  };
  EXPECT_EQ(code_and_path({{"animation", {{"clip", "Walk"}}}}), std::pair(422, std::string("/sheet/animation/clip")));
  EXPECT_EQ(code_and_path({{"animation", {{"clip", "Bend"}, {"frames", 0}}}}).first, 400);
  EXPECT_EQ(code_and_path({{"animation", {{"clip", "Bend"}, {"frames", 10000}}}}).first, 400);
  EXPECT_EQ(code_and_path({{"animation", {{{"clip", "Bend"}}, {{"clip", 9}}}}}),
            std::pair(422, std::string("/sheet/animation/1/clip")));
  EXPECT_EQ(code_and_path({{"animation", {{"clip", "Bend"}, {"frames", 4}, {"fps", 10}}}}),
            std::pair(400, std::string("/sheet/animation/fps")));
  EXPECT_EQ(code_and_path({{"animation", {{"clip", "Bend"}}}}, {{"animation", {{"clip", "Bend"}}}}),
            std::pair(400, std::string("/animation")));
  EXPECT_EQ(
      code_and_path({{"frames", 64}, {"pitches", {0, 10, 20}}, {"animation", {{"clip", "Bend"}, {"frames", 64}}}}),
      std::pair(400, std::string("/sheet/animation")));
}

}  // namespace
}  // namespace toond::test
