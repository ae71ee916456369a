// A sheet's files over HTTP, on Blender's walking character
// (tests/exported/blender/make_walker.py), 4 directions × 6 frames of its
// Walk at 96²: sheet.pack trims and packs the tiles so that each packed
// frame put back at spriteSourceSize is its unpacked tile exactly, on a
// fraction of the grid's area; ?atlas=aseprite and ?atlas=godot answer the
// .aseprite file and the Godot resource, packed or not; the CLI picks them
// from -o's extension; what cannot be packed or written is refused with
// the field at fault. (The files read by an independent .aseprite reader
// and a Godot grammar reader: tests/browser/sheet_files.test.mjs.)
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "image/png_codec.h"
#include "support/ase_reader.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

class SheetFiles : public SharedDaemonTest {
 protected:
  static const std::string& walker() {
    static const std::string id = [] {
      auto client = daemon().client();
      const auto res = upload_files(client, TOOND_EXPORTED_DIR "/blender", {"walker.glb"});
      if (!res || (res->status != 200 && res->status != 201)) {
        ADD_FAILURE() << (res ? res->body : "no answer");
        return std::string();
      }
      return json::parse(res->body)["id"].get<std::string>();
    }();
    return id;
  }

  // The default walk sheet of the docs: 4 directions from yaw 0, 6 frames
  // of Walk, 96² on a transparent background, dimetric.
  static json walk(const json& sheet_fields = json::object()) {
    json sheet = {{"frames", 4}, {"yaw_start", 0}, {"animation", {{"clip", "Walk"}, {"frames", 6}}}};
    sheet.update(sheet_fields);
    return {{"model", walker()},
            {"width", 96},
            {"height", 96},
            {"background", {0, 0, 0, 0}},
            {"camera", {{"preset", "dimetric"}}},
            {"sheet", sheet}};
  }

  // The answer's body, from a request that must succeed with `type`.
  static std::string answer(const std::string& path, const json& params, const std::string& type) {
    auto client = daemon().client();
    const auto res = post_json(client, path, params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << path << " answered " << (res ? std::to_string(res->status) + ": " + res->body : "nothing");
      return {};
    }
    EXPECT_EQ(res->get_header_value("Content-Type"), type) << path;
    return res->body;
  }

  // The walk drawn as both layers (sheet.layers), answered as `output`.
  static json layered(const std::string& output, const json& sheet_fields = json::object()) {
    json params = walk(sheet_fields);
    params["sheet"]["layers"] = {"color", "lines"};
    params["output"] = output;
    return params;
  }

  // The walk's sheet of each layer, asked for alone as the docs say it:
  // the colour with outline and contour off, and output lines.
  static image::Image colour_without_lines() {
    json params = walk();
    params["outline"] = {{"enabled", false}};
    params["contour"] = {{"enabled", false}};
    return image::decode_png(answer("/render", params, "image/png"));
  }
  static image::Image lines_alone() {
    json params = walk();
    params["output"] = "lines";
    return image::decode_png(answer("/render", params, "image/png"));
  }

  static json atlas_in(const std::string& png) {
    const auto text = png_text(png, "toond:atlas");
    if (!text) {
      ADD_FAILURE() << "no toond:atlas in the PNG";
      return json::object();
    }
    return json::parse(*text);
  }
};

// The tile a packed frame stands for: its pixels put back at
// spriteSourceSize in a transparent sourceSize canvas.
image::Image unpacked_tile(const image::Image& packed, const json& frame) {
  const image::Image piece = tile_of(packed, frame["frame"]);
  const json& at = frame["spriteSourceSize"];
  image::Image tile{frame["sourceSize"]["w"], frame["sourceSize"]["h"], {}};
  tile.rgba.assign(static_cast<std::size_t>(tile.width) * tile.height * 4, 0);
  for (int y = 0; y < piece.height; ++y) {
    std::copy_n(piece.pixel(0, y), piece.width * 4, tile.pixel(at["x"].get<int>(), at["y"].get<int>() + y));
  }
  return tile;
}

TEST_F(SheetFiles, EachPackedFrameAtItsSourceOffsetIsItsTileOnAFractionOfTheArea) {
  ASSERT_FALSE(walker().empty());
  const std::string grid_png = answer("/render", walk(), "image/png");
  const std::string packed_png = answer("/render", walk({{"pack", true}}), "image/png");
  ASSERT_FALSE(grid_png.empty() || packed_png.empty());
  const image::Image grid = image::decode_png(grid_png);
  const image::Image packed = image::decode_png(packed_png);
  const json grid_atlas = atlas_in(grid_png);
  const json atlas = atlas_in(packed_png);
  ASSERT_EQ(atlas["frames"].size(), 24u);
  EXPECT_EQ(atlas["meta"]["size"], (json{{"w", packed.width}, {"h", packed.height}}));
  EXPECT_EQ(atlas["meta"]["packed"], true);
  EXPECT_EQ(atlas["meta"]["frameTags"], grid_atlas["meta"]["frameTags"]) << "packing changes no tag";
  int trimmed = 0;
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const json& was = grid_atlas["frames"][name];
    EXPECT_EQ(unpacked_tile(packed, frame).rgba, tile_of(grid, was["frame"]).rgba) << "frame " << name;
    EXPECT_EQ(frame["anchor"], was["anchor"]) << name;
    EXPECT_EQ(frame["duration"], was["duration"]) << name;
    EXPECT_EQ(frame["sourceSize"], (json{{"w", 96}, {"h", 96}}));
    trimmed += frame["trimmed"].get<bool>();
  }
  EXPECT_EQ(trimmed, 24) << "every walker tile has transparent margins";
  const double share =
      static_cast<double>(packed.width) * packed.height / (static_cast<double>(grid.width) * grid.height);
  std::printf("packed walk sheet: %dx%d of the grid's %dx%d, %.3f of its area\n", packed.width, packed.height,
              grid.width, grid.height, share);
  EXPECT_LE(share, 0.60);
  EXPECT_EQ(json::parse(answer("/render?atlas=json", walk({{"pack", true}}), "application/json")), atlas)
      << "?atlas=json draws the packed sheet for its atlas";
}

// sheet.layers: every frame of the .aseprite file has a cel in each layer,
// and each is its tile of the sheet of that layer asked for on its own.
TEST_F(SheetFiles, TheAsepriteFileOfTwoLayersHoldsTheColourAndTheLinesAsAskedApart) {
  ASSERT_FALSE(walker().empty());
  const AseRead ase = read_aseprite(answer("/render?atlas=aseprite", layered("color"), "application/octet-stream"));
  ASSERT_EQ(ase.frames, 24);
  EXPECT_EQ(ase.layers, (std::vector<std::string>{"color", "lines"})) << "bottom first: lines over the colour";
  const std::string grid_png = answer("/render", walk(), "image/png");
  const json grid_atlas = atlas_in(grid_png);
  const image::Image sheets[] = {colour_without_lines(), lines_alone()};
  EXPECT_NE(sheets[0].rgba, image::decode_png(grid_png).rgba) << "the colour with its lines is not the colour layer";
  std::vector<std::vector<int>> cels(2, std::vector<int>(24, 0));
  for (const AseRead::Cel& cel : ase.cels) {
    ASSERT_TRUE(cel.layer == 0 || cel.layer == 1) << cel.layer;
    ++cels[static_cast<std::size_t>(cel.layer)][static_cast<std::size_t>(cel.frame)];
    const image::Image tile =
        tile_of(sheets[static_cast<std::size_t>(cel.layer)], grid_atlas["frames"][std::to_string(cel.frame)]["frame"]);
    EXPECT_EQ(visible_pixels(cel_on_canvas(cel, 96, 96)), visible_pixels(tile.rgba))
        << "frame " << cel.frame << " of " << ase.layers[static_cast<std::size_t>(cel.layer)];
  }
  EXPECT_EQ(cels, std::vector<std::vector<int>>(2, std::vector<int>(24, 1))) << "a cel per layer per frame";
  EXPECT_EQ(answer("/render?atlas=aseprite", layered("lines", {{"pack", true}}), "application/octet-stream"),
            answer("/render?atlas=aseprite", layered("color"), "application/octet-stream"))
      << "the same file whichever layer is the output, packed or not";
}

// Packed with sheet.layers, each frame is cut to the pixels of both layers:
// the colour and the lines sheets of the request have one atlas, and each
// of their frames put back is its tile of that layer's grid sheet.
TEST_F(SheetFiles, PackedLayersShareOneAtlasAndOverlayAsTheirGrids) {
  ASSERT_FALSE(walker().empty());
  const std::string colour_png = answer("/render", layered("color", {{"pack", true}}), "image/png");
  const std::string lines_png = answer("/render", layered("lines", {{"pack", true}}), "image/png");
  ASSERT_FALSE(colour_png.empty() || lines_png.empty());
  const json atlas = atlas_in(colour_png);
  EXPECT_EQ(atlas_in(lines_png), atlas) << "one packing for both layers";
  const image::Image packed[] = {image::decode_png(colour_png), image::decode_png(lines_png)};
  EXPECT_EQ(packed[0].width, packed[1].width);
  EXPECT_EQ(packed[0].height, packed[1].height);
  const json grid_atlas = atlas_in(answer("/render", walk(), "image/png"));
  const image::Image grids[] = {colour_without_lines(), lines_alone()};
  for (const auto& [name, frame] : atlas["frames"].items()) {
    for (std::size_t layer = 0; layer < 2; ++layer) {
      EXPECT_EQ(visible_pixels(unpacked_tile(packed[layer], frame).rgba),
                visible_pixels(tile_of(grids[layer], grid_atlas["frames"][name]["frame"]).rgba))
          << "frame " << name << (layer ? " lines" : " colour");
    }
  }
  // Packed alone, the colour without lines is cut to its fills, inside the
  // hull outline: a packing of its own, which the lines would not fit.
  json bare_packed_alone = walk({{"pack", true}});
  bare_packed_alone["outline"] = {{"enabled", false}};
  const json bare_atlas = atlas_in(answer("/render", bare_packed_alone, "image/png"));
  int smaller = 0;
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const json& own = bare_atlas["frames"][name]["frame"];
    smaller +=
        own["w"].get<int>() * own["h"].get<int>() < frame["frame"]["w"].get<int>() * frame["frame"]["h"].get<int>();
  }
  EXPECT_EQ(smaller, 24) << "every frame of the layers is cut wider than the fills alone";
}

TEST_F(SheetFiles, PaddingAndPowerOfTwoShapeThePackedSheet) {
  const std::string png =
      answer("/render", walk({{"pack", true}, {"padding", 2}, {"power_of_two", true}}), "image/png");
  ASSERT_FALSE(png.empty());
  const image::Image packed = image::decode_png(png);
  EXPECT_EQ(packed.width & (packed.width - 1), 0) << packed.width;
  EXPECT_EQ(packed.height & (packed.height - 1), 0) << packed.height;
  const json atlas = atlas_in(png);
  std::vector<json> rects;
  for (const auto& [name, frame] : atlas["frames"].items()) rects.push_back(frame["frame"]);
  for (std::size_t i = 0; i < rects.size(); ++i) {
    for (std::size_t j = i + 1; j < rects.size(); ++j) {
      const json& a = rects[i];
      const json& b = rects[j];
      const bool apart = a["x"].get<int>() + a["w"].get<int>() + 2 <= b["x"].get<int>() ||
                         b["x"].get<int>() + b["w"].get<int>() + 2 <= a["x"].get<int>() ||
                         a["y"].get<int>() + a["h"].get<int>() + 2 <= b["y"].get<int>() ||
                         b["y"].get<int>() + b["h"].get<int>() + 2 <= a["y"].get<int>();
      EXPECT_TRUE(apart) << i << " and " << j << " are closer than the padding";
    }
  }
}

TEST_F(SheetFiles, TheAsepriteFileIsTheSamePackedOrNotAndNotThePng) {
  const std::string file = answer("/render?atlas=aseprite", walk(), "application/octet-stream");
  ASSERT_GT(file.size(), 128u);
  EXPECT_EQ(static_cast<unsigned char>(file[4]) | (static_cast<unsigned char>(file[5]) << 8), 0xA5E0)
      << "Aseprite's magic number";
  EXPECT_EQ(static_cast<unsigned char>(file[6]) | (static_cast<unsigned char>(file[7]) << 8), 24) << "frames";
  // Cels are cut to their pixels either way, so packing changes no byte.
  EXPECT_EQ(answer("/render?atlas=aseprite", walk({{"pack", true}}), "application/octet-stream"), file);
  // The result cache keeps the image and the file apart.
  EXPECT_EQ(answer("/render", walk(), "image/png").substr(1, 3), "PNG");
  EXPECT_EQ(answer("/render?atlas=aseprite", walk(), "application/octet-stream"), file);
}

// The regions of the Godot resource are the atlas's frames, packed or not,
// and it names the PNG as ?texture says.
TEST_F(SheetFiles, TheGodotResourceCutsTheAtlasFrames) {
  for (const bool pack : {false, true}) {
    const json params = walk({{"pack", pack}});
    const json atlas = json::parse(answer("/render?atlas=json", params, "application/json"));
    const std::string tres =
        answer("/render?atlas=godot&texture=res://sprites/walk.png", params, "text/plain; charset=utf-8");
    EXPECT_NE(tres.find("path=\"res://sprites/walk.png\""), std::string::npos);
    const std::regex region(
        R"re(id="AtlasTexture_([0-9]+)"\]\natlas = ExtResource\("1_sheet"\)\nregion = Rect2\(([0-9]+), ([0-9]+), ([0-9]+), ([0-9]+)\))re");
    int regions = 0;
    for (auto it = std::sregex_iterator(tres.begin(), tres.end(), region); it != std::sregex_iterator(); ++it) {
      const json& rect = atlas["frames"][(*it)[1].str()]["frame"];
      EXPECT_EQ((json{{"x", std::stoi((*it)[2])},
                      {"y", std::stoi((*it)[3])},
                      {"w", std::stoi((*it)[4])},
                      {"h", std::stoi((*it)[5])}}),
                rect)
          << "frame " << (*it)[1] << (pack ? " packed" : "");
      ++regions;
    }
    EXPECT_EQ(regions, 24);
    EXPECT_EQ(tres.find("margin = ") != std::string::npos, pack) << "a margin only where frames are trimmed";
  }
  EXPECT_NE(answer("/render?atlas=godot", walk(), "text/plain; charset=utf-8").find("path=\"sheet.png\""),
            std::string::npos)
      << "by default, the PNG beside the .tres under the atlas's meta.image";
}

TEST_F(SheetFiles, WhatCannotBePackedOrWrittenIsRefusedWithItsField) {
  auto client = daemon().client();
  const json small = {{"width", 32}, {"height", 32}, {"sheet", {{"frames", 2}}}};
  const auto refused = [&](const std::string& path, json params, const std::string& field) {
    const auto res = post_json(client, path, params);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << path << " " << params.dump() << ": " << res->body;
    EXPECT_EQ(error_of(res)["path"], field) << path << " " << params.dump();
  };
  json animated = small;
  animated["sheet"]["animate"] = true;
  json packed_animation = animated;
  packed_animation["sheet"]["pack"] = true;
  refused("/render", packed_animation, "/sheet/pack");
  json packed_depth = small;
  packed_depth["sheet"]["pack"] = true;
  packed_depth["output"] = "depth";
  refused("/render", packed_depth, "/sheet/pack");
  json depth = small;
  depth["output"] = "depth";
  refused("/render?atlas=aseprite", depth, "/output");
  refused("/render?atlas=aseprite", animated, "/sheet/animate");
  refused("/render?atlas=godot", animated, "/sheet/animate");
  refused("/render?atlas=godot", {{"width", 32}, {"height", 32}}, "/sheet");
  refused("/render?atlas=png", small, "?atlas");
  refused("/render?texture=walk.png", small, "?texture");
  for (const char* bad : {"/etc/walk.png", "http://x/walk.png", "C:\\walk.png", "res://"}) {
    refused(std::string("/render?atlas=godot&texture=") + httplib::detail::encode_query_param(bad), small, "?texture");
  }
}

TEST_F(SheetFiles, TheCliPicksTheFileFromTheExtension) {
  ASSERT_FALSE(walker().empty());
  const auto dir = make_temp_dir("toon-sheet-files");
  const auto cli = [&](const std::string& out) {
    return run_process({TOON_BINARY, "render",
                        "--model",   walker(),
                        "--set",     "width=48",
                        "--set",     "height=48",
                        "--set",     "sheet.frames=2",
                        "--set",     "sheet.animation.clip=Walk",
                        "--set",     "sheet.animation.frames=3",
                        "--set",     "sheet.pack=true",
                        "-o",        (dir / out).string(),
                        "--server",  daemon().url()});
  };
  const auto ase = cli("walk.aseprite");
  ASSERT_EQ(ase.status, 0) << ase.err;
  const std::string file = read_file(dir / "walk.aseprite");
  ASSERT_GT(file.size(), 8u);
  EXPECT_EQ(static_cast<unsigned char>(file[5]), 0xA5);
  const auto godot = cli("walk.tres");
  ASSERT_EQ(godot.status, 0) << godot.err;
  const std::string tres = read_file(dir / "walk.tres");
  EXPECT_NE(tres.find("path=\"walk.png\""), std::string::npos) << tres.substr(0, 200);
  const std::string png = read_file(dir / "walk.png");
  const json atlas = json::parse(png_text(png, "toond:atlas").value_or("{}"));
  EXPECT_EQ(atlas["meta"]["packed"], true);
  for (const auto& [name, frame] : atlas["frames"].items()) {
    const json& r = frame["frame"];
    const std::string rect =
        "region = Rect2(" + r["x"].dump() + ", " + r["y"].dump() + ", " + r["w"].dump() + ", " + r["h"].dump() + ")";
    EXPECT_NE(tres.find(rect), std::string::npos) << "the .tres cuts the PNG written beside it: " << rect;
  }
}

}  // namespace
}  // namespace toond::test
