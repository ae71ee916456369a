// Sprite sheets without GL: where tiles go, the framing every frame shares,
// the atlas, the sprite camera presets and the sheet's limits.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "limit_error.h"
#include "param_schema.h"
#include "pipeline/budget.h"
#include "pipeline/frames.h"
#include "pipeline/render_params_wire.h"
#include "presets.h"
#include "render/atlas/sheet_atlas.h"
#include "render/plan/camera.h"
#include "render/plan/sheet_layout.h"

namespace toond::render {
namespace {

using nlohmann::json;

// Each frame's plan as far as the atlas reads it: its view of a box two
// units tall standing on the origin, and the framing they share.
std::vector<FramePlan> plans_of(const SheetLayout& layout, const RenderParams& p) {
  auto scene = std::make_shared<SceneFrame>();
  scene->bounds = {{-1, 0, -1}, {1, 2, 1}};
  std::vector<FramePlan> plans;
  for (const SheetFrame& frame : layout.frames) {
    FramePlan plan{.params = frame_params(p, layout, frame), .scene = scene};
    plan.camera = fit_camera(plan.params.camera, scene->bounds, static_cast<double>(p.width) / p.height);
    plans.push_back(std::move(plan));
  }
  return plans;
}

RenderParams params_of(const json& request) {
  const json expanded = proto::Presets::builtin().expand(request);
  return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(expanded));
}

TEST(SheetLayout, AbsentFieldsComeFromTheCameraAndAFullTurn) {
  const RenderParams p = params_of({{"camera", {{"yaw", 20}, {"pitch", 10}}}, {"sheet", {{"frames", 6}}}});
  ASSERT_TRUE(p.sheet);
  EXPECT_EQ(p.sheet->columns, 6) << "one row per pitch";
  EXPECT_DOUBLE_EQ(p.sheet->yaw_start_deg, 20);
  EXPECT_DOUBLE_EQ(p.sheet->yaw_step_deg, 60);
  EXPECT_EQ(p.sheet->pitches_deg, std::vector<double>{10});
  EXPECT_FALSE(params_of(json::object()).sheet) << "no sheet unless asked";
}

TEST(SheetLayout, RowsPerColumnsAndPerPitchWithPaddingBetweenTiles) {
  SheetParams sheet;
  sheet.frames = 5;
  sheet.columns = 2;
  sheet.yaw_start_deg = 350;
  sheet.yaw_step_deg = 10;
  sheet.pitches_deg = {0, 30};
  sheet.padding = 3;
  const SheetLayout layout = layout_sheet(sheet, 40, 30);
  EXPECT_EQ(layout.columns, 2);
  EXPECT_EQ(layout.rows, 6) << "3 rows for 5 frames, for each of 2 pitches";
  EXPECT_EQ(layout.width, 2 * 40 + 3);
  EXPECT_EQ(layout.height, 6 * 30 + 5 * 3);
  ASSERT_EQ(layout.frames.size(), 10u);
  // The second pitch starts a new row after the first pitch's short row.
  EXPECT_EQ(layout.frames[4].x, 0);
  EXPECT_EQ(layout.frames[4].y, 2 * 33);
  EXPECT_EQ(layout.frames[5].y, 3 * 33);
  EXPECT_EQ(layout.frames[5].pitch_deg, 30);
  EXPECT_EQ(layout.frames[3].x, 43);
  // Yaws wrap into [0, 360).
  EXPECT_DOUBLE_EQ(layout.frames[0].yaw_deg, 350);
  EXPECT_DOUBLE_EQ(layout.frames[1].yaw_deg, 0);
  EXPECT_DOUBLE_EQ(layout.frames[2].yaw_deg, 10);
}

TEST(SheetLayout, TilesStayInsideTheSheetAndNeverOverlap) {
  SheetParams sheet;
  sheet.frames = 7;
  sheet.columns = 3;
  sheet.pitches_deg = {10, 20, 30};
  sheet.padding = 2;
  const SheetLayout layout = layout_sheet(sheet, 16, 24);
  std::set<std::pair<int, int>> covered;
  for (const SheetFrame& f : layout.frames) {
    EXPECT_GE(f.x, 0);
    EXPECT_GE(f.y, 0);
    EXPECT_LE(f.x + 16, layout.width);
    EXPECT_LE(f.y + 24, layout.height);
    for (int y = f.y; y < f.y + 24; ++y) {
      for (int x = f.x; x < f.x + 16; ++x) EXPECT_TRUE(covered.insert({x, y}).second) << "overlap at " << x << "," << y;
    }
  }
}

TEST(SheetLayout, MoreColumnsThanFramesGiveOneRow) {
  SheetParams sheet;
  sheet.frames = 3;
  sheet.columns = 10;
  sheet.pitches_deg = {0};
  const SheetLayout layout = layout_sheet(sheet, 10, 10);
  EXPECT_EQ(layout.width, 30);
  EXPECT_EQ(layout.rows, 1);
}

// A long box seen end-on needs less room than seen side-on: fitted alone,
// each view scales it differently; framed with all views, every frame has
// the distance (perspective) or frame (orthographic) of the widest.
TEST(SheetFraming, EveryFrameSharesTheWidestFit) {
  const scene::Bounds long_box{{-3, -1, -0.5f}, {3, 1, 0.5f}};
  for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    CameraParams end_on;
    end_on.projection = projection;
    end_on.yaw_deg = 90;
    end_on.pitch_deg = 0;  // level, like the framed views below
    CameraParams side_on = end_on;
    side_on.yaw_deg = 0;
    const CameraSetup alone_end = fit_camera(end_on, long_box, 1.0);
    const CameraSetup alone_side = fit_camera(side_on, long_box, 1.0);
    const double alone_end_size = projection == Projection::Orthographic ? alone_end.half_height : alone_end.distance;
    const double alone_side_size =
        projection == Projection::Orthographic ? alone_side.half_height : alone_side.distance;
    ASSERT_LT(alone_end_size * 1.5, alone_side_size) << "the test needs views that fit differently";

    end_on.framed_views = side_on.framed_views = {{0, 0}, {90, 0}};
    const CameraSetup shared_end = fit_camera(end_on, long_box, 1.0);
    const CameraSetup shared_side = fit_camera(side_on, long_box, 1.0);
    EXPECT_DOUBLE_EQ(shared_end.distance, shared_side.distance);
    EXPECT_DOUBLE_EQ(shared_end.half_height, shared_side.half_height);
    if (projection == Projection::Orthographic) {
      EXPECT_DOUBLE_EQ(shared_end.half_height, alone_side.half_height);
    } else {
      EXPECT_DOUBLE_EQ(shared_end.distance, alone_side.distance);
    }
    // The view itself is still the frame's own.
    EXPECT_NEAR(glm::normalize(shared_end.eye - shared_end.target).x, 1.0, 1e-12);
  }
}

TEST(SheetFraming, WithoutFramedViewsASingleRenderFitsAsBefore) {
  const scene::Bounds box{{-1, -2, -1}, {1, 2, 1}};
  CameraParams params;
  params.yaw_deg = 30;
  params.pitch_deg = 15;
  const CameraSetup plain = fit_camera(params, box, 1.5);
  params.framed_views = {{30, 15}};
  const CameraSetup framed = fit_camera(params, box, 1.5);
  EXPECT_EQ(plain.distance, framed.distance) << "its own view adds nothing";
  EXPECT_EQ(plain.view, framed.view);
  EXPECT_EQ(plain.projection, framed.projection);
}

TEST(SheetFraming, FrameParamsTurnTheViewAndDropTheSheet) {
  const RenderParams p = params_of({{"sheet", {{"frames", 4}, {"pitches", {0, 45}}}}});
  const SheetLayout layout = layout_sheet(*p.sheet, p.width, p.height);
  const RenderParams one = frame_params(p, layout, layout.frames[6]);
  EXPECT_FALSE(one.sheet);
  EXPECT_DOUBLE_EQ(one.camera.yaw_deg, layout.frames[6].yaw_deg);
  EXPECT_DOUBLE_EQ(one.camera.pitch_deg, 45);
  EXPECT_EQ(one.camera.framed_views.size(), 8u);
}

// A clip's frames show for whole milliseconds, each within one of its
// exact share, adding up to the clip's length row by row; a turntable's
// frames for frame_ms.
TEST(SheetLayout, FramesShowForWholeMillisecondsThatAddUpToTheClip) {
  SheetParams sheet;
  sheet.frames = 2;
  sheet.pitches_deg = {30};
  sheet.frame_ms = 70;
  SheetClip walk;
  walk.name = "Walk";
  walk.duration = 0.9583;  // 23 frames at 24 fps
  walk.frame_count = 7;
  SheetClip still;
  still.name = "Still";
  still.duration = 0;
  still.frame_count = 2;
  sheet.clips = {walk, still};
  const SheetLayout layout = layout_sheet(sheet, 8, 8);
  ASSERT_EQ(layout.frames.size(), 2u * 7 + 2u * 2);
  for (int row = 0; row < 2; ++row) {
    int sum = 0;
    for (int k = 0; k < 7; ++k) {
      const SheetFrame& f = layout.frames[static_cast<std::size_t>(row * 7 + k)];
      EXPECT_NEAR(f.duration_ms, 958.3 / 7, 1.0) << "row " << row << ", frame " << k;
      sum += f.duration_ms;
    }
    EXPECT_EQ(sum, 958) << "row " << row;
  }
  EXPECT_EQ(layout.frames[14].duration_ms, 70) << "a clip of no length shows each frame for frame_ms";
  sheet.clips.clear();
  for (const SheetFrame& f : layout_sheet(sheet, 8, 8).frames) EXPECT_EQ(f.duration_ms, 70);
}

// A clip resolved as the pipeline resolves it (pipeline/clips.h): its span
// and the span's length.
SheetClip resolved_clip(const std::string& name, scene::ClipRange span, int frames, bool loop) {
  SheetClip clip;
  clip.name = name;
  clip.range = span;
  clip.span = span;
  clip.duration = span.end - span.start;
  clip.frame_count = frames;
  clip.loop = loop;
  return clip;
}

// A range's frames count from its start on the file's time base; a loop
// leaves its end out.
TEST(SheetLayout, ARangesFramesRunFromItsStartAndALoopLeavesItsEndOut) {
  SheetParams sheet;
  sheet.frames = 2;
  sheet.pitches_deg = {30};
  sheet.clips = {resolved_clip("anim", {2.8, 3.2}, 4, true)};
  const SheetLayout layout = layout_sheet(sheet, 8, 8);
  ASSERT_EQ(layout.frames.size(), 8u);
  for (int row = 0; row < 2; ++row) {
    for (int k = 0; k < 4; ++k) {
      const SheetFrame& f = layout.frames[static_cast<std::size_t>(row * 4 + k)];
      EXPECT_NEAR(f.time, 2.8 + 0.1 * k, 1e-12) << "row " << row << ", frame " << k;
      EXPECT_EQ(f.duration_ms, 100);
    }
  }
}

// A one-shot's frames reach its last pose: start + k · length / (frames − 1);
// each shows for that step, the last too, so a row lasts its length and
// one step more. One frame: the start, for the length.
TEST(SheetLayout, AOneShotsFramesEndOnItsLastPose) {
  SheetParams sheet;
  sheet.frames = 1;
  sheet.pitches_deg = {30};
  sheet.clips = {resolved_clip("attack", {1.0, 2.0}, 5, false), resolved_clip("hit", {0.5, 0.75}, 1, false)};
  const SheetLayout layout = layout_sheet(sheet, 8, 8);
  ASSERT_EQ(layout.frames.size(), 6u);
  EXPECT_EQ(layout.columns, 5);
  for (int k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(layout.frames[static_cast<std::size_t>(k)].time, 1.0 + 0.25 * k) << "frame " << k;
    EXPECT_EQ(layout.frames[static_cast<std::size_t>(k)].duration_ms, 250) << "frame " << k;
  }
  EXPECT_DOUBLE_EQ(layout.frames[4].time, 2.0) << "the last frame is the range's end";
  EXPECT_DOUBLE_EQ(layout.frames[5].time, 0.5);
  EXPECT_EQ(layout.frames[5].duration_ms, 250);
}

// Aseprite writes a tag's "repeat" (a string) only when set; "1" plays it
// once. A loop's tag has none, as a looping Aseprite tag has none.
TEST(SheetAtlas, AOneShotsTagsPlayOnceAndALoopsRepeat) {
  RenderParams p = params_of({{"width", 16}, {"height", 16}, {"sheet", {{"frames", 2}}}});
  p.sheet->clips = {resolved_clip("Walk", {0.0, 1.0}, 4, true), resolved_clip("Die", {1.0, 2.0}, 3, false)};
  const SheetLayout layout = layout_sheet(*p.sheet, p.width, p.height);
  const json atlas = sheet_atlas(layout, p, plans_of(layout, p), "sheet.png");
  const json& tags = atlas["meta"]["frameTags"];
  ASSERT_EQ(tags.size(), 4u);
  for (const json& tag : tags) {
    if (tag["clip"] == "Walk") {
      EXPECT_FALSE(tag.contains("repeat")) << tag;
    } else {
      EXPECT_EQ(tag["repeat"], "1") << tag;
    }
  }
  EXPECT_EQ(tags[3]["clip"], "Die");
  EXPECT_DOUBLE_EQ(atlas["frames"][std::to_string(tags[3]["to"].get<int>())]["time"].get<double>(), 2.0);
}

TEST(SheetAtlas, FollowsAsepritesHashLayoutWithYawAndPitch) {
  const RenderParams p = params_of({{"width", 32}, {"height", 48}, {"sheet", {{"frames", 8}, {"columns", 4}}}});
  const SheetLayout layout = layout_sheet(*p.sheet, p.width, p.height);
  const nlohmann::ordered_json listed = sheet_atlas(layout, p, plans_of(layout, p), "sheet.png");
  // Named by index, as Aseprite's {frame} names them, and listed in order.
  std::vector<std::string> names;
  for (const auto& [name, frame] : listed["frames"].items()) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"0", "1", "2", "3", "4", "5", "6", "7"}));
  const json atlas = listed;
  const json& f = atlas["frames"]["5"];
  EXPECT_EQ(f["frame"], (json{{"x", 32}, {"y", 48}, {"w", 32}, {"h", 48}}));
  EXPECT_EQ(f["spriteSourceSize"], (json{{"x", 0}, {"y", 0}, {"w", 32}, {"h", 48}}));
  EXPECT_EQ(f["sourceSize"], (json{{"w", 32}, {"h", 48}}));
  EXPECT_EQ(f["rotated"], false);
  EXPECT_EQ(f["trimmed"], false);
  EXPECT_DOUBLE_EQ(f["yaw"].get<double>(), std::fmod(30.0 + 5 * 45.0, 360.0));
  EXPECT_DOUBLE_EQ(f["pitch"].get<double>(), 15.0);
  // The foot of an upright model stands on the tile's vertical middle line,
  // below its centre, at the same place in every frame.
  EXPECT_NEAR(f["pivot"]["x"].get<double>(), 0.5, 1e-9);
  EXPECT_GT(f["pivot"]["y"].get<double>(), 0.5);
  EXPECT_LT(f["pivot"]["y"].get<double>(), 1.0);
  EXPECT_NEAR(f["pivot"]["y"].get<double>(), atlas["frames"]["0"]["pivot"]["y"].get<double>(), 1e-9);
  EXPECT_EQ(f["anchor"], f["pivot"]) << "anchor for Pixi and Phaser, the same point";
  EXPECT_EQ(f["duration"], 100) << "a turntable frame shows for frame_ms";
  // A turntable is one tag (and one Pixi animation) per pitch.
  EXPECT_EQ(atlas["meta"]["frameTags"],
            json::parse(R"([{"name": "turn", "from": 0, "to": 7, "direction": "forward", "pitch": 15.0}])"));
  EXPECT_EQ(atlas["animations"], (json{{"turn", {"0", "1", "2", "3", "4", "5", "6", "7"}}}));
  const json& meta = atlas["meta"];
  EXPECT_EQ(meta["image"], "sheet.png");
  EXPECT_EQ(meta["size"], (json{{"w", 128}, {"h", 96}}));
  EXPECT_EQ(meta["padding"], 0);
  EXPECT_EQ(meta["camera"]["projection"], "perspective");
  EXPECT_GT(meta["camera"]["distance"].get<double>(), 0);
}

TEST(SheetBudget, TheWholeSheetCountsAgainstTheLimits) {
  const auto check_render_budget = [](const RenderParams& p, const pipeline::RenderLimits& l) {
    pipeline::check_render_budget(p, pipeline::layout_of(p), l);
  };
  pipeline::RenderLimits limits;
  limits.max_output_pixels = 64 * 64 * 8;
  limits.max_samples = 64 * 64 * 8 * 4;
  const RenderParams fits = params_of({{"width", 64}, {"height", 64}, {"sheet", {{"frames", 8}}}});
  EXPECT_NO_THROW(check_render_budget(fits, limits));
  const RenderParams too_many = params_of({{"width", 64}, {"height", 64}, {"sheet", {{"frames", 9}}}});
  try {
    check_render_budget(too_many, limits);
    ADD_FAILURE() << "9 tiles of 64² passed a limit of 8";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.limit(), "--max-output-pixels");
    EXPECT_EQ(e.status(), 422);
  }
  const RenderParams too_fine = params_of({{"width", 64}, {"height", 64}, {"msaa", 8}, {"sheet", {{"frames", 8}}}});
  try {
    check_render_budget(too_fine, limits);
    ADD_FAILURE() << "8 frames × msaa 8 passed a sample limit of 8 × msaa 4";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.limit(), "--max-samples");
  }
}

// A depth, normal or id layer draws one sample a pixel whatever msaa and
// supersample say: a limit those would pass is no reason to refuse it.
TEST(SheetBudget, DataLayersCountTheSamplesTheyDraw) {
  const auto check_render_budget = [](const RenderParams& p, const pipeline::RenderLimits& l) {
    pipeline::check_render_budget(p, pipeline::layout_of(p), l);
  };
  pipeline::RenderLimits limits;
  limits.max_samples = 256 * 256 * 4;
  const json heavy = {{"width", 256}, {"height", 256}, {"msaa", 8}, {"supersample", 2}};
  EXPECT_THROW(check_render_budget(params_of(heavy), limits), LimitError);
  for (const char* layer : {"depth", "normal", "id"}) {
    json request = heavy;
    request["output"] = layer;
    EXPECT_NO_THROW(check_render_budget(params_of(request), limits)) << layer;
  }
  json lines = heavy;
  lines["output"] = "lines";
  EXPECT_THROW(check_render_budget(params_of(lines), limits), LimitError) << "the lines layer draws what colour does";
}

TEST(CameraPresets, SpriteViewsAreOrthographicAndGivenFieldsWin) {
  const RenderParams iso = params_of({{"camera", {{"preset", "isometric"}}}});
  EXPECT_EQ(iso.camera.projection, Projection::Orthographic);
  EXPECT_NEAR(iso.camera.pitch_deg, glm::degrees(std::atan(1.0 / std::sqrt(2.0))), 1e-3);
  EXPECT_DOUBLE_EQ(iso.camera.yaw_deg, 45);
  const RenderParams dimetric = params_of({{"preset", "anime"}, {"camera", {{"preset", "dimetric"}, {"yaw", 10}}}});
  EXPECT_EQ(dimetric.camera.projection, Projection::Orthographic);
  EXPECT_DOUBLE_EQ(dimetric.camera.pitch_deg, 30);
  EXPECT_DOUBLE_EQ(dimetric.camera.yaw_deg, 10) << "the request's own yaw";
  EXPECT_EQ(dimetric.mode, params_of({{"preset", "anime"}}).mode) << "combines with a look preset";
}

// Where the schema refuses `request`, or "(accepted)".
std::string schema_refusal_path(const json& request) {
  try {
    proto::ParamSchema::render_params().validate(request);
  } catch (const RequestError& e) {
    return e.path();
  }
  return "(accepted)";
}

TEST(SheetSchema, BadSheetsAreRefusedWithTheirPath) {
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"frames", 0}}}}), "/sheet/frames");
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"frames", 65}}}}), "/sheet/frames");
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"columns", 0}}}}), "/sheet/columns");
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"pitches", {0, 1, 2, 3, 4, 5, 6, 7, 8}}}}}), "/sheet/pitches");
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"pitches", {90}}}}}), "/sheet/pitches/0");
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"padding", 65}}}}), "/sheet/padding");
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"fps", 5}}}}), "/sheet/fps");
  EXPECT_EQ(schema_refusal_path({{"camera", {{"preset", "cabinet"}}}}), "/camera/preset");
  EXPECT_EQ(schema_refusal_path({{"sheet", json::object()}}), "(accepted)");
}

TEST(SheetSchema, SetFromTextReachesTheSheet) {
  json params = json::object();
  proto::ParamSchema::render_params().set_from_text(params, "sheet.frames", "8");
  proto::ParamSchema::render_params().set_from_text(params, "sheet.pitches", "[0,30]");
  EXPECT_EQ(params, (json{{"sheet", {{"frames", 8}, {"pitches", {0, 30}}}}}));
}

// sheet.animation is one clip's entry or a list of them: the schema holds
// the entry twice, and the two must say the same.
TEST(SheetSchema, AClipEntryIsTheSameInBothForms) {
  const json& schema = proto::ParamSchema::render_params().document();
  const json& forms = schema["properties"]["sheet"]["properties"]["animation"]["oneOf"];
  ASSERT_EQ(forms.size(), 2u);
  EXPECT_EQ(forms[0]["type"], "object");
  EXPECT_EQ(forms[1]["type"], "array");
  EXPECT_EQ(forms[0], forms[1]["items"]);
  for (const char* field : {"clip", "frames", "fps", "range", "loop"}) {
    EXPECT_TRUE(forms[0]["properties"].contains(field)) << field;
  }
}

TEST(SheetSchema, ARangeIsTwoSecondsAndLoopABoolean) {
  const json walk = {{"clip", "Walk"}, {"range", {2.8, 3.1}}, {"loop", false}};
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"animation", walk}}}}), "(accepted)");
  EXPECT_EQ(schema_refusal_path({{"sheet", {{"animation", {walk, walk}}}}}), "(accepted)");
  EXPECT_EQ(schema_refusal_path({{"animation", {{"clip", "Walk"}, {"range", {2.8, 3.1}}}}}), "(accepted)");
  EXPECT_EQ(schema_refusal_path({{"animation", {{"clip", "Walk"}, {"range", {2.8}}}}}), "/animation/range");
  EXPECT_EQ(schema_refusal_path({{"animation", {{"clip", "Walk"}, {"range", {1, 2, 3}}}}}), "/animation/range");
  EXPECT_EQ(schema_refusal_path({{"animation", {{"clip", "Walk"}, {"range", {"1", 2}}}}}), "/animation/range/0");
  EXPECT_EQ(schema_refusal_path({{"animation", {{"clip", "Walk"}, {"loop", false}}}}), "/animation/loop");
}

// The CLI's --set: a range as the two numbers a user types, into an entry
// or the top-level animation.
TEST(SheetSchema, SetFromTextTakesARangeAndALoop) {
  const auto& schema = proto::ParamSchema::render_params();
  json params = json::object();
  schema.set_from_text(params, "sheet.animation.clip", "walk");
  schema.set_from_text(params, "sheet.animation.range", "5.6,6.23");
  schema.set_from_text(params, "sheet.animation.loop", "false");
  schema.set_from_text(params, "animation.range", "[2.8, 3.1]");
  EXPECT_EQ(params, (json{{"sheet", {{"animation", {{"clip", "walk"}, {"range", {5.6, 6.23}}, {"loop", false}}}}},
                          {"animation", {{"range", {2.8, 3.1}}}}}));
}

}  // namespace
}  // namespace toond::render
