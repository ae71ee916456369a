// A rigged, animated glTF from a real exporter (Blender's bending bar:
// tests/exported/blender/make_rigged.py) posed through the default request
// with `animation`: what the upload says of it, frames of a clip framed
// alike and never cut off, time wrapping, every output layer following the
// pose, the errors, and the CLI.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "image/png_codec.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using json = nlohmann::json;

class AnimatedModel : public SharedDaemonTest {
 protected:
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
    return render_ok(client, {{"model", id()}, {"width", 96}, {"height", 96}, {"output", output},
                              {"animation", {{"clip", clip}, {"time", time}}}});
  }
};

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

TEST_F(AnimatedModel, APoseDiffersFromTheRestAndTimeWrapsRoundTheLoop) {
  const image::Image start = pose(0.0);
  const image::Image quarter = pose(0.25);
  EXPECT_NE(start.rgba, quarter.rgba);
  EXPECT_EQ(pose(1.0).rgba, start.rgba);      // the clip's duration is its start again
  EXPECT_EQ(pose(1.25).rgba, quarter.rgba);   // past the end: round again
  EXPECT_EQ(pose(-0.75).rgba, quarter.rgba);  // before the start: back from the end
  EXPECT_EQ(pose(0.25, "color", 0).rgba, quarter.rgba);  // the clip by its index
}

TEST_F(AnimatedModel, EveryFrameOfAClipIsFramedAlikeAndNeverCutOff) {
  // Frame by frame at 24 per second: nothing touches the image's edge, and
  // a pixel row and column well inside hold the model at every frame.
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

}  // namespace
}  // namespace toond::test
