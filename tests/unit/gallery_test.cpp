// `toon gallery` without a daemon: the look table against the schema, the
// per-model views and lights, the --set commands it prints, model folder
// selection, contact-sheet assembly and the HTML page.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_args.h"
#include "cli_test_helpers.h"
#include "gallery_looks.h"
#include "gallery_page.h"
#include "gallery_sheet.h"
#include "param_schema.h"
#include "presets.h"

namespace toond::cli::gallery {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const proto::ParamSchema& schema() { return proto::ParamSchema::render_params(); }

const std::string kModelId = "0123456789abcdef0123456789abcdef";

std::vector<Look> all_looks() {
  std::vector<Look> looks = preset_looks(proto::Presets::builtin().document(), schema());
  for (const Look& l : effect_looks()) looks.push_back(l);
  return looks;
}

json preset_params_of(const Look& look) {
  if (!look.is_preset) return json();
  return proto::Presets::builtin().document().at(look.name).at("params");
}

std::vector<ModelView> some_views() {
  return {view_for_model("stanford-bunny", schema()), view_for_model("spot", schema()),
          view_for_model("windmill", schema()), ModelView{180, 0}, ModelView{-90, 40}};
}

using cli_test::contains;
using cli_test::usage_error;

// ---------------------------------------------------------------- looks

TEST(GalleryLooks, EveryEffectLookValidatesAgainstTheSchema) {
  ASSERT_GE(effect_looks().size(), 15u);
  for (const Look& look : effect_looks()) {
    EXPECT_NO_THROW(validate_look(look, schema())) << look.name;
    EXPECT_FALSE(look.is_preset) << look.name;
    EXPECT_FALSE(look.description.empty()) << look.name;
  }
}

TEST(GalleryLooks, EveryRequestTheGallerySendsValidates) {
  const ModelFrame frame{{0.1, 0.8, -0.2}, 1.5};
  for (const Look& look : all_looks()) {
    for (const ModelView& view : some_views()) {
      const json params = render_params(look, preset_params_of(look), view, frame, 96, kModelId, schema());
      EXPECT_NO_THROW(schema().validate(params)) << look.name << " " << params.dump();
      EXPECT_EQ(params["width"], 96);
      EXPECT_EQ(params["height"], 96);
      EXPECT_EQ(params["model"], kModelId);
    }
  }
}

TEST(GalleryLooks, NamesAreUniqueAndSafeAsFileNames) {
  std::set<std::string> names;
  const std::regex safe("[a-z0-9_]+");
  for (const Look& look : all_looks()) {
    EXPECT_TRUE(names.insert(look.name).second) << "duplicate look " << look.name;
    EXPECT_TRUE(std::regex_match(look.name, safe)) << look.name;
  }
  // Every preset and the effects the gallery promises are there.
  for (const char* name :
       {"bw_comic", "noir", "default", "specular_off", "rim", "halftone_dots", "halftone_checker", "contour_even",
        "contour_fresnel", "shadows_floor", "two_tone", "color_ramp", "outline_texture", "outline_material",
        "supersample_2", "msaa_1", "msaa_8", "lights_sum", "point_light"}) {
    EXPECT_TRUE(names.count(name)) << name;
  }
}

TEST(GalleryLooks, PresetsComeInTheSchemasOrder) {
  const std::vector<Look> looks = preset_looks(proto::Presets::builtin().document(), schema());
  const json& order = schema().document()["properties"]["preset"]["enum"];
  ASSERT_EQ(looks.size(), order.size());
  for (std::size_t i = 0; i < looks.size(); ++i) {
    EXPECT_EQ(looks[i].name, order[i].get<std::string>());
    EXPECT_TRUE(looks[i].is_preset);
    EXPECT_EQ(looks[i].params, (json{{"preset", looks[i].name}}));
    EXPECT_NO_THROW(validate_look(looks[i], schema()));
  }
}

TEST(GalleryLooks, AnUnknownPresetFromTheServerComesLastAndFailsValidation) {
  json presets = proto::Presets::builtin().document();
  presets["zz_new_look"] = {{"description", "newer than this toon"}, {"params", json::object()}};
  const std::vector<Look> looks = preset_looks(presets, schema());
  ASSERT_FALSE(looks.empty());
  EXPECT_EQ(looks.back().name, "zz_new_look");
  const std::string message = usage_error([&] { validate_look(looks.back(), schema()); });
  EXPECT_TRUE(contains(message, "zz_new_look")) << message;
}

TEST(GalleryLooks, ARenamedParameterFailsNamingTheLook) {
  const Look bad{"rim_typo", "", json::parse(R"({"rim": {"enabled": true, "colour": [1, 1, 1]}})"), false};
  const std::string message = usage_error([&] { validate_look(bad, schema()); });
  EXPECT_TRUE(contains(message, "rim_typo")) << message;
  EXPECT_TRUE(contains(message, "colour")) << message;
  EXPECT_TRUE(contains(message, "gallery_looks.cpp")) << message;
}

// ---------------------------------------------------------------- views and lights

// The unit vector from the model toward the camera, as the schema defines yaw and pitch.
std::array<double, 3> toward_camera(const ModelView& v) {
  const double y = v.yaw * std::numbers::pi / 180, p = v.pitch * std::numbers::pi / 180;
  return {std::sin(y) * std::cos(p), std::sin(p), std::cos(y) * std::cos(p)};
}

TEST(GalleryViews, SpotIsSeenFromTheFrontOthersGetTheDefaultCamera) {
  EXPECT_EQ(view_for_model("spot", schema()).yaw, -140);
  const ModelView bunny = view_for_model("stanford-bunny", schema());
  const json& camera = schema().document()["properties"]["camera"]["properties"];
  EXPECT_EQ(bunny.yaw, camera["yaw"]["default"].get<double>());
  EXPECT_EQ(bunny.pitch, camera["pitch"]["default"].get<double>());
}

TEST(GalleryViews, TheDefaultViewSendsNoCameraAndNoLights) {
  const Look& plain = effect_looks().front();
  ASSERT_EQ(plain.name, "default");
  const json params =
      render_params(plain, json(), view_for_model("utah-teapot", schema()), ModelFrame{}, 64, "", schema());
  EXPECT_EQ(params, (json{{"width", 64}, {"height", 64}}));
}

TEST(GalleryViews, EveryDirectionalLightLightsTheSideTheCameraSees) {
  const ModelFrame frame;
  for (const ModelView& view : some_views()) {
    for (const Look& look : all_looks()) {
      json params = render_params(look, preset_params_of(look), view, frame, 64, "", schema());
      // A sheet's lights are in view space, where the camera looks from +z.
      const bool sheet = params.contains("sheet");
      const auto c = sheet ? std::array<double, 3>{0, 0, 1} : toward_camera(view);
      // Without "lights" in the request the preset's or the schema's
      // default lights apply, which is right for the default camera (or a
      // sheet's turning one) only.
      if (!params.contains("lights")) {
        EXPECT_TRUE(view.yaw == 30 || sheet) << look.name;
        const json preset = preset_params_of(look);
        params["lights"] = preset.is_object() && preset.contains("lights")
                               ? preset["lights"]
                               : schema().document()["properties"]["lights"]["default"];
      }
      for (const json& light : params["lights"]) {
        if (light.value("type", "directional") != "directional") continue;
        const json& d = light["direction"];
        const double len = std::hypot(d[0].get<double>(), d[1].get<double>(), d[2].get<double>());
        // The light travels along d, so it comes from -d: from the camera's half of the sky.
        const double facing =
            -(d[0].get<double>() * c[0] + d[1].get<double>() * c[1] + d[2].get<double>() * c[2]) / len;
        EXPECT_GT(facing, 0.0) << look.name << " yaw " << view.yaw << " " << light.dump();
      }
    }
  }
}

TEST(GalleryViews, LightsTurnWithTheCameraYaw) {
  const Look& plain = effect_looks().front();
  const json spot = render_params(plain, json(), ModelView{-150, 15}, ModelFrame{}, 64, "", schema());
  EXPECT_EQ(spot["camera"], (json{{"yaw", -150}, {"pitch", 15}}));
  // The default light [-0.4, -0.5, -1] turned by -180°: x and z change sign.
  ASSERT_EQ(spot["lights"].size(), 1u);
  const json& d = spot["lights"][0]["direction"];
  EXPECT_NEAR(d[0].get<double>(), 0.4, 1e-9);
  EXPECT_NEAR(d[1].get<double>(), -0.5, 1e-9);
  EXPECT_NEAR(d[2].get<double>(), 1.0, 1e-9);
}

TEST(GalleryViews, PointLightsAreScaledToTheModel) {
  const Look* point = nullptr;
  for (const Look& l : effect_looks()) {
    if (l.name == "point_light") point = &l;
  }
  ASSERT_NE(point, nullptr);
  const json& table_light = point->params["lights"][0];
  const ModelFrame frame{{10, 20, 30}, 100};
  const json params = render_params(*point, json(), ModelView{30, 15}, frame, 64, "", schema());
  const json& light = params["lights"][0];
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(light["position"][i].get<double>(), frame.center[i] + 100 * table_light["position"][i].get<double>(),
                1e-6)
        << i;
  }
  EXPECT_NEAR(light["radius"].get<double>(), 100 * table_light["radius"].get<double>(), 1e-6);
}

TEST(GalleryViews, FrameFromObjVertices) {
  const ModelFrame f = frame_from_obj("# comment\nv 0 0 0\nvt 5 5\nvn 9 9 9\n  v -2 4 1 1.0\nv\t2 0 -1\nf 1 2 3\n");
  EXPECT_DOUBLE_EQ(f.center[0], 0);
  EXPECT_DOUBLE_EQ(f.center[1], 2);
  EXPECT_DOUBLE_EQ(f.center[2], 0);
  EXPECT_DOUBLE_EQ(f.radius, std::sqrt(4.0 + 4.0 + 1.0));
  const ModelFrame empty = frame_from_obj("o nothing\n");
  EXPECT_DOUBLE_EQ(empty.radius, 1);
}

// ---------------------------------------------------------------- commands

TEST(GalleryCommands, SetArgumentsReproduceEveryRequest) {
  const ModelFrame frame{{0, 0.5, 0}, 0.8};
  for (const Look& look : all_looks()) {
    for (const ModelView& view : some_views()) {
      json params = render_params(look, preset_params_of(look), view, frame, 128, kModelId, schema());
      json rebuilt = json::object();
      for (const auto& [key, value] : set_arguments(params)) {
        ASSERT_NO_THROW(schema().set_from_text(rebuilt, key, value)) << look.name << " " << key << "=" << value;
      }
      params.erase("model");
      EXPECT_EQ(rebuilt, params) << look.name;
    }
  }
}

TEST(GalleryCommands, RenderCommandQuotesForTheShell) {
  const json params = {{"preset", "noir"},
                       {"width", 64},
                       {"model", kModelId},
                       {"lights", json::array({{{"type", "directional"}, {"direction", {0, -1, 0}}}})}};
  const std::string cmd = render_command("../shared/models/my model/it's.obj", params, "noir.png");
  EXPECT_EQ(cmd,
            "toon render '../shared/models/my model/it'\\''s.obj' "
            "--set 'lights=[{\"direction\":[0,-1,0],\"type\":\"directional\"}]' "
            "--set preset=noir --set width=64 -o noir.png");
  EXPECT_EQ(shell_quote("camera.yaw=-140.0"), "camera.yaw=-140.0");
  EXPECT_EQ(shell_quote(""), "''");
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("$HOME"), "'$HOME'");
}

// ---------------------------------------------------------------- model folders

class GalleryModels : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("toon-gallery-models-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    for (const char* d : {"spot", "two", "none", "nested/deeper", "utah-teapot"}) fs::create_directories(dir_ / d);
    touch("spot/spot.obj");
    touch("two/a.obj");
    touch("two/b.OBJ");
    touch("none/readme.txt");
    touch("nested/deeper/x.obj");
    touch("utah-teapot/teapot.obj");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void touch(const char* rel) { std::ofstream(dir_ / rel) << "v 0 0 0\n"; }
  static std::vector<std::string> names(const ModelSelection& s) {
    std::vector<std::string> out;
    for (const auto& m : s.models) out.push_back(m.name);
    return out;
  }
  fs::path dir_;
};

TEST_F(GalleryModels, DefaultsAreTheNamedModelsThatArePresent) {
  const ModelSelection s = select_models(dir_, false, {});
  EXPECT_EQ(names(s), (std::vector<std::string>{"spot", "utah-teapot"}));
  EXPECT_EQ(s.models[0].obj_path, dir_ / "spot" / "spot.obj");
  EXPECT_EQ(s.notes.size(), default_model_names().size() - 2);
}

TEST_F(GalleryModels, AllTakesEveryFolderWithExactlyOneObjAndNotesTheRest) {
  const ModelSelection s = select_models(dir_, true, {});
  EXPECT_EQ(names(s), (std::vector<std::string>{"spot", "utah-teapot"}));
  ASSERT_EQ(s.notes.size(), 3u);
  EXPECT_TRUE(contains(s.notes[0], "nested")) << s.notes[0];
  EXPECT_TRUE(contains(s.notes[0], "no .obj")) << s.notes[0];
  EXPECT_TRUE(contains(s.notes[2], "two")) << s.notes[2];
  EXPECT_TRUE(contains(s.notes[2], "2 .obj")) << s.notes[2];
}

TEST_F(GalleryModels, OnlyKeepsItsOrderAndRejectsWhatItCannotRender) {
  EXPECT_EQ(names(select_models(dir_, false, {"utah-teapot", "spot"})),
            (std::vector<std::string>{"utah-teapot", "spot"}));
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_, false, {"two"}); }), "2 .obj"));
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_, false, {"missing"}); }), "missing"));
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_, false, {"spot", "spot"}); }), "twice"));
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_ / "none", true, {}); }), "no model folder"));
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_ / "absent", false, {}); }), "not a folder"));
}

// One default model comes as glTF: a folder's OBJ that toon writes as a .glb.
TEST_F(GalleryModels, TheDefaultsIncludeOneGltfModel) {
  const auto& defaults = default_model_names();
  ASSERT_EQ(std::count_if(defaults.begin(), defaults.end(), [](const std::string& n) { return n.ends_with(".glb"); }),
            1);
  fs::create_directories(dir_ / "bob");
  touch("bob/bob_tri.obj");
  const ModelSelection s = select_models(dir_, false, {});
  EXPECT_EQ(names(s), (std::vector<std::string>{"spot", "utah-teapot", "bob.glb"}));
  const ModelFolder& glb = s.models.back();
  EXPECT_TRUE(glb.as_glb);
  EXPECT_EQ(glb.folder, "bob");
  EXPECT_EQ(glb.obj_path, dir_ / "bob" / "bob_tri.obj");
  EXPECT_FALSE(s.models.front().as_glb);
  EXPECT_EQ(s.models.front().folder, "spot");
  // --all: every folder, then the glTF model again.
  EXPECT_EQ(names(select_models(dir_, true, {})), (std::vector<std::string>{"bob", "spot", "utah-teapot", "bob.glb"}));
}

TEST_F(GalleryModels, FolderDotGlbIsThatFoldersObjAsGltfUnlessAFolderHasTheName) {
  ModelSelection s = select_models(dir_, false, {"spot.glb", "spot"});
  EXPECT_EQ(names(s), (std::vector<std::string>{"spot.glb", "spot"}));
  EXPECT_TRUE(s.models[0].as_glb);
  EXPECT_EQ(s.models[0].obj_path, dir_ / "spot" / "spot.obj");
  EXPECT_FALSE(s.models[1].as_glb);
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_, false, {"two.glb"}); }), "2 .obj"));
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_, false, {"missing.glb"}); }), "not found"));
  EXPECT_TRUE(contains(usage_error([&] { select_models(dir_, false, {".glb"}); }), "not found"));

  fs::create_directories(dir_ / "odd.glb");
  touch("odd.glb/model.obj");
  s = select_models(dir_, false, {"odd.glb"});
  EXPECT_FALSE(s.models[0].as_glb);
  EXPECT_EQ(s.models[0].folder, "odd.glb");
}

// ---------------------------------------------------------------- arguments

TEST(GalleryArgs, DefaultsAndFlags) {
  const Options d = parse_args({"gallery", "-o", "out"}, std::nullopt);
  EXPECT_EQ(d.verb, Verb::gallery);
  EXPECT_EQ(d.models_dir, "../shared/models");
  EXPECT_EQ(d.size, 256);
  EXPECT_FALSE(d.all_models);
  EXPECT_TRUE(d.only.empty());
  EXPECT_EQ(d.output, "out");

  const Options o = parse_args({"gallery", "--models=m", "--size", "64", "--only", "spot,bob", "--only=windmill", "-o",
                                "out", "--server", "http://h:1"},
                               std::nullopt);
  EXPECT_EQ(o.models_dir, "m");
  EXPECT_EQ(o.size, 64);
  EXPECT_EQ(o.only, (std::vector<std::string>{"spot", "bob", "windmill"}));
  EXPECT_EQ(o.server, "http://h:1");
  EXPECT_TRUE(parse_args({"gallery", "--all", "-o", "x"}, std::nullopt).all_models);
}

TEST(GalleryArgs, MistakesAreUsageErrors) {
  EXPECT_TRUE(contains(usage_error([] { parse_args({"gallery"}, std::nullopt); }), "-o OUTDIR"));
  EXPECT_TRUE(contains(usage_error([] { parse_args({"gallery", "-o", "-"}, std::nullopt); }), "folder"));
  EXPECT_TRUE(contains(usage_error([] { parse_args({"gallery", "--size", "8", "-o", "x"}, std::nullopt); }), "--size"));
  EXPECT_TRUE(contains(usage_error([] {
                         parse_args({"gallery", "--size", "1e3", "-o", "x"}, std::nullopt);
                       }),
                       "--size"));
  EXPECT_TRUE(contains(usage_error([] {
                         parse_args({"gallery", "--all", "--only", "spot", "-o", "x"}, std::nullopt);
                       }),
                       "--all"));
  EXPECT_TRUE(contains(usage_error([] {
                         parse_args({"gallery", "--only", "a,,b", "-o", "x"}, std::nullopt);
                       }),
                       "--only"));
  EXPECT_TRUE(contains(usage_error([] { parse_args({"gallery", "spot", "-o", "x"}, std::nullopt); }), "no arguments"));
  EXPECT_TRUE(contains(usage_error([] {
                         parse_args({"gallery", "--set", "width=9", "-o", "x"}, std::nullopt);
                       }),
                       "gallery does not take --set"));
  EXPECT_TRUE(contains(usage_error([] {
                         parse_args({"render", "--size", "64", "-o", "x.png"}, std::nullopt);
                       }),
                       "render does not take --size"));
  EXPECT_FALSE(usage_text(Verb::gallery).empty());
  EXPECT_TRUE(contains(usage_text(Verb::none), "gallery"));
}

// ---------------------------------------------------------------- contact sheet

image::Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255) {
  image::Image img;
  img.width = w;
  img.height = h;
  img.rgba.resize(static_cast<std::size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = r;
      p[1] = g;
      p[2] = b;
      p[3] = a;
    }
  }
  return img;
}

std::array<int, 4> at(const image::Image& img, int x, int y) {
  const std::uint8_t* p = img.pixel(x, y);
  return {p[0], p[1], p[2], p[3]};
}

std::array<int, 4> rgba(const unsigned char (&c)[4]) { return {c[0], c[1], c[2], c[3]}; }

TEST(GallerySheet, ThumbnailFactorKeepsThumbnailsSmall) {
  EXPECT_EQ(thumbnail_factor(64), 1);
  EXPECT_EQ(thumbnail_factor(128), 1);
  EXPECT_EQ(thumbnail_factor(129), 2);
  EXPECT_EQ(thumbnail_factor(192), 2);
  EXPECT_EQ(thumbnail_factor(256), 2);
  EXPECT_EQ(thumbnail_factor(512), 4);
  for (int size : {16, 100, 200, 300, 1000, 4096}) EXPECT_LE(size / thumbnail_factor(size), kMaxThumbnail);
}

TEST(GallerySheet, ThumbnailsAreBoxFilteredAndCropped) {
  // A 4×4 image: left half black, right half white → 2×2 black | white.
  image::Image img = solid(4, 4, 0, 0, 0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 2; x < 4; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = p[1] = p[2] = 255;
    }
  }
  const image::Image t = make_thumbnail(img, 2);
  EXPECT_EQ(t.width, 2);
  EXPECT_EQ(t.height, 2);
  EXPECT_EQ(at(t, 0, 1), (std::array<int, 4>{0, 0, 0, 255}));
  EXPECT_EQ(at(t, 1, 0), (std::array<int, 4>{255, 255, 255, 255}));
  // 5×7 by 2: the odd column and row are dropped.
  const image::Image c = make_thumbnail(solid(5, 7, 10, 200, 30), 2);
  EXPECT_EQ(c.width, 2);
  EXPECT_EQ(c.height, 3);
  EXPECT_EQ(at(c, 1, 2), (std::array<int, 4>{10, 200, 30, 255}));
  EXPECT_EQ(make_thumbnail(solid(3, 3, 1, 2, 3), 1).rgba, solid(3, 3, 1, 2, 3).rgba);
}

TEST(GallerySheet, SizeGapAndPlacement) {
  const image::Image red = solid(3, 2, 255, 0, 0);
  const image::Image green = solid(3, 2, 0, 255, 0);
  const image::Image blue = solid(3, 2, 0, 0, 255);
  // Two rows of three columns; the second row is short and has a failed cell.
  const image::Image sheet = assemble_contact_sheet({{&red, &green, &blue}, {&blue, nullptr}}, 3, 2, 2);
  EXPECT_EQ(sheet.width, 3 * 3 + 4 * 2);
  EXPECT_EQ(sheet.height, 2 * 2 + 3 * 2);

  const auto bg = rgba(kSheetBackground);
  // The border and the gaps.
  EXPECT_EQ(at(sheet, 0, 0), bg);
  EXPECT_EQ(at(sheet, 1, 3), bg);
  EXPECT_EQ(at(sheet, 5, 2), bg);  // between columns 0 and 1
  EXPECT_EQ(at(sheet, 6, 2), bg);
  EXPECT_EQ(at(sheet, 2, 4), bg);  // between rows
  EXPECT_EQ(at(sheet, 2, 5), bg);
  EXPECT_EQ(at(sheet, sheet.width - 1, sheet.height - 1), bg);
  // Cell (r, c) starts at (2 + c·5, 2 + r·4).
  EXPECT_EQ(at(sheet, 2, 2), (std::array<int, 4>{255, 0, 0, 255}));
  EXPECT_EQ(at(sheet, 4, 3), (std::array<int, 4>{255, 0, 0, 255}));
  EXPECT_EQ(at(sheet, 7, 2), (std::array<int, 4>{0, 255, 0, 255}));
  EXPECT_EQ(at(sheet, 12, 3), (std::array<int, 4>{0, 0, 255, 255}));
  EXPECT_EQ(at(sheet, 2, 6), (std::array<int, 4>{0, 0, 255, 255}));
  EXPECT_EQ(at(sheet, 7, 6), rgba(kSheetMissing));  // the failed render
  EXPECT_EQ(at(sheet, 9, 7), rgba(kSheetMissing));
  EXPECT_EQ(at(sheet, 12, 6), bg);  // no third cell in row 1
}

TEST(GallerySheet, SmallImagesAreCentredLargeOnesClippedTransparentComposited) {
  const image::Image dot = solid(1, 1, 255, 255, 255);
  const image::Image big = solid(9, 9, 0, 0, 0);
  const image::Image clear = solid(3, 3, 255, 0, 0, 0);
  const image::Image sheet = assemble_contact_sheet({{&dot, &big, &clear}}, 3, 3, 1);
  EXPECT_EQ(sheet.width, 3 * 3 + 4);
  EXPECT_EQ(sheet.height, 3 + 2);
  const auto bg = rgba(kSheetBackground);
  EXPECT_EQ(at(sheet, 2, 2), (std::array<int, 4>{255, 255, 255, 255}));  // centre of cell 0
  EXPECT_EQ(at(sheet, 1, 1), bg);
  for (int x = 5; x < 8; ++x) EXPECT_EQ(at(sheet, x, 1), (std::array<int, 4>{0, 0, 0, 255})) << x;
  EXPECT_EQ(at(sheet, 4, 1), bg);  // the big image does not spill into the gap
  EXPECT_EQ(at(sheet, 8, 1), bg);
  EXPECT_EQ(at(sheet, 10, 2), bg);  // fully transparent shows the sheet
}

// ---------------------------------------------------------------- page

TEST(GalleryPage, HtmlEscaping) {
  EXPECT_EQ(html_escape(R"(<a href="x">Tom & Jerry's</a>)"),
            "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&#39;s&lt;/a&gt;");
  EXPECT_EQ(html_escape("plain"), "plain");
  EXPECT_EQ(url_path("my model/it's #1.png"), "my%20model/it%27s%20%231.png");
  EXPECT_EQ(url_path("kenney-cube-pet-dog/bw_comic.png"), "kenney-cube-pet-dog/bw_comic.png");
}

TEST(GalleryPage, EveryRenderIsThereEscaped) {
  PageInfo info;
  info.contact_sheet = "contact-sheet.png";
  info.size = 64;
  info.renderer = "llvmpipe <LLVM>";
  PageModel m{"a<b>&c", "models/a<b>&c/x.obj", "", {}};
  m.renders.push_back({"noir", "Film \"noir\"", "a<b>&c/noir.png", json{{"preset", "noir"}},
                       "toon render 'x' --set preset=noir -o noir.png", ""});
  m.renders.push_back({"rim", "Rim", "", json{{"rim", {{"enabled", true}}}}, "toon render",
                       "error 400 invalid_parameter at /rim: <oops>"});
  const std::string page = gallery_page(info, {m});
  EXPECT_TRUE(contains(page, "<!DOCTYPE html>"));
  EXPECT_TRUE(contains(page, "src=\"contact-sheet.png\""));
  EXPECT_TRUE(contains(page, "src=\"a%3Cb%3E%26c/noir.png\""));
  EXPECT_TRUE(contains(page, "<h2>a&lt;b&gt;&amp;c</h2>"));
  EXPECT_TRUE(contains(page, "Film &quot;noir&quot;"));
  EXPECT_TRUE(contains(page, "llvmpipe &lt;LLVM&gt;"));
  EXPECT_TRUE(contains(page, "&quot;preset&quot;: &quot;noir&quot;"));
  EXPECT_TRUE(contains(page, "toon render &#39;x&#39; --set preset=noir -o noir.png"));
  EXPECT_TRUE(contains(page, "&lt;oops&gt;"));
  EXPECT_TRUE(contains(page, "1 failed"));
  EXPECT_FALSE(contains(page, "<oops>"));
  EXPECT_FALSE(contains(page, "a<b>"));
  EXPECT_FALSE(contains(page, "<script"));
}

TEST(GalleryPage, PrettyJsonKeepsShortThingsOnOneLine) {
  const json params = json::parse(R"({"camera": {"yaw": -140, "pitch": 12}, "width": 64,
      "shading": {"ramp": [{"at": -1, "color": [0.34, 0.32, 0.55]}, {"at": 0.2, "color": [0.8, 0.72, 0.8]},
                           {"at": 0.6, "color": [1, 0.96, 0.86]}]}})");
  const std::string text = pretty_json(params);
  EXPECT_EQ(json::parse(text), params);
  EXPECT_TRUE(contains(text, "\"camera\": {\"pitch\": 12, \"yaw\": -140}")) << text;
  EXPECT_TRUE(contains(text, "{\"at\": -1, \"color\": [0.34, 0.32, 0.55]}")) << text;
  EXPECT_EQ(pretty_json(json::object()), "{}");
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    EXPECT_LE(end - start, 78u) << text.substr(start, end - start);
    start = end + 1;
  }
}

}  // namespace
}  // namespace toond::cli::gallery
