// The files a sheet is answered as, without a daemon: tiles cut to their
// pixels, the skyline packer, a packed sheet and its atlas, .aseprite files
// read back field by field as Aseprite's published format lays them out,
// and Godot SpriteFrames resources.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "sheet_files/aseprite_file.h"
#include "sheet_files/godot_sprite_frames.h"
#include "sheet_files/packed_sheet.h"
#include "sheet_files/skyline_pack.h"
#include "sheet_files/tile_trim.h"
#include "support/ase_reader.h"

namespace toond::sheet_files {
namespace {

using json = nlohmann::ordered_json;
using test::AseRead;
using test::read_aseprite;

image::Image blank(int w, int h) { return {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4, 0)}; }

void put(image::Image& im, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
  std::uint8_t* p = im.pixel(x, y);
  p[0] = r;
  p[1] = g;
  p[2] = b;
  p[3] = a;
}

// A grid sheet as toond lays one out, with its atlas: tile k holds a block
// of a colour of its own at a place of its own, a half-transparent pixel at
// the block's corner and, outside it, a pixel of colour with no alpha (which
// trimming must ignore); the tiles listed in `empty` hold nothing.
struct GridSheet {
  image::Image image;
  json atlas;
  int tile_w = 0;
  int tile_h = 0;
};

GridSheet grid_sheet(int columns, int rows, int tile_w, int tile_h, int padding, const std::vector<int>& empty) {
  GridSheet sheet;
  sheet.tile_w = tile_w;
  sheet.tile_h = tile_h;
  const int width = columns * tile_w + (columns - 1) * padding;
  const int height = rows * tile_h + (rows - 1) * padding;
  sheet.image = blank(width, height);
  json frames = json::object();
  json tags = json::array();
  for (int k = 0; k < columns * rows; ++k) {
    const int tx = (k % columns) * (tile_w + padding);
    const int ty = (k / columns) * (tile_h + padding);
    if (std::find(empty.begin(), empty.end(), k) == empty.end()) {
      const int bx = tx + 2 + (k * 7) % (tile_w - 14);
      const int by = ty + 1 + (k * 5) % (tile_h - 14);
      const int bw = 6 + k % 4;
      const int bh = 8 + k % 3;
      for (int y = by; y < by + bh; ++y) {
        for (int x = bx; x < bx + bw; ++x) put(sheet.image, x, y, 40 * k % 256, 200 - 10 * k, 90, 255);
      }
      put(sheet.image, bx + bw, by + bh, 10, 20, 30, 128);
      put(sheet.image, tx + tile_w - 1, ty + tile_h - 1, 255, 0, 0, 0);
    }
    frames[std::to_string(k)] = {
        {"frame", {{"x", tx}, {"y", ty}, {"w", tile_w}, {"h", tile_h}}},
        {"rotated", false},
        {"trimmed", false},
        {"spriteSourceSize", {{"x", 0}, {"y", 0}, {"w", tile_w}, {"h", tile_h}}},
        {"sourceSize", {{"w", tile_w}, {"h", tile_h}}},
        {"duration", 83 + k % 2},
        {"anchor", {{"x", 0.5}, {"y", k < columns ? 0.875 : 0.75}}},
        {"index", k},
    };
  }
  for (int r = 0; r < rows; ++r) {
    json tag = {{"name", "Walk_" + std::to_string(90 * r)},
                {"from", r * columns},
                {"to", r * columns + columns - 1},
                {"direction", "forward"}};
    if (r == rows - 1) tag["repeat"] = "1";
    tags.push_back(tag);
  }
  sheet.atlas = {{"frames", frames},
                 {"meta",
                  {{"image", "sheet.png"},
                   {"size", {{"w", width}, {"h", height}}},
                   {"frameTags", tags},
                   {"padding", padding},
                   {"columns", columns},
                   {"rows", rows}}}};
  return sheet;
}

// The tile of `name` as a tile_w × tile_h image: from the grid, or from a
// packed sheet by placing its frame at spriteSourceSize.
image::Image tile_of(const image::Image& sheet, const json& entry) {
  const json& f = entry.at("frame");
  const json& s = entry.at("spriteSourceSize");
  image::Image tile = blank(entry.at("sourceSize").at("w").get<int>(), entry.at("sourceSize").at("h").get<int>());
  for (int y = 0; y < f.at("h").get<int>(); ++y) {
    for (int x = 0; x < f.at("w").get<int>(); ++x) {
      const std::uint8_t* from = sheet.pixel(f.at("x").get<int>() + x, f.at("y").get<int>() + y);
      std::copy(from, from + 4, tile.pixel(s.at("x").get<int>() + x, s.at("y").get<int>() + y));
    }
  }
  return tile;
}

// A fully transparent pixel's colour shows nowhere: compared as (0,0,0,0).
std::vector<std::uint8_t> visible(const image::Image& im) { return test::visible_pixels(im.rgba); }

TEST(TileTrim, BoundsHoldEveryPixelWithAlphaAndNothingElse) {
  image::Image im = blank(20, 10);
  put(im, 3, 2, 0, 0, 0, 1);
  put(im, 12, 7, 9, 9, 9, 255);
  put(im, 18, 9, 255, 255, 255, 0);  // colour without alpha
  const PixelRect b = visible_bounds(im, {0, 0, 20, 10});
  EXPECT_EQ(b.x, 3);
  EXPECT_EQ(b.y, 2);
  EXPECT_EQ(b.w, 10);
  EXPECT_EQ(b.h, 6);
  const PixelRect right = visible_bounds(im, {10, 0, 10, 10});
  EXPECT_EQ(right.x, 12);
  EXPECT_EQ(right.w, 1);
  EXPECT_EQ(visible_bounds(im, {14, 0, 6, 10}).w, 0) << "a tile of transparent pixels has no bounds";
}

std::vector<PackSize> mixed_sizes() {
  std::vector<PackSize> sizes;
  unsigned seed = 12345;
  for (int i = 0; i < 37; ++i) {
    seed = seed * 1103515245u + 12345u;
    sizes.push_back({1 + static_cast<int>((seed >> 8) % 60), 1 + static_cast<int>((seed >> 18) % 45)});
  }
  return sizes;
}

// Every rectangle inside the sheet, and any two at least `padding` apart.
void expect_apart_and_inside(const std::vector<PackSize>& sizes, const Packing& p, int padding) {
  ASSERT_EQ(p.places.size(), sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const PackPlace& a = p.places[i];
    EXPECT_GE(a.x, 0);
    EXPECT_GE(a.y, 0);
    EXPECT_LE(a.x + sizes[i].w, p.width) << i;
    EXPECT_LE(a.y + sizes[i].h, p.height) << i;
    for (std::size_t j = i + 1; j < sizes.size(); ++j) {
      const PackPlace& b = p.places[j];
      const bool apart = a.x + sizes[i].w + padding <= b.x || b.x + sizes[j].w + padding <= a.x ||
                         a.y + sizes[i].h + padding <= b.y || b.y + sizes[j].h + padding <= a.y;
      EXPECT_TRUE(apart) << i << " and " << j;
    }
  }
}

TEST(SkylinePack, RectanglesStayInsideAndPaddingApart) {
  const std::vector<PackSize> sizes = mixed_sizes();
  for (int padding : {0, 1, 3}) {
    const Packing p = pack_rects(sizes, {.padding = padding});
    expect_apart_and_inside(sizes, p, padding);
    // No padding around the edge: something touches the right and bottom.
    bool right = false;
    bool bottom = false;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      right = right || p.places[i].x + sizes[i].w == p.width;
      bottom = bottom || p.places[i].y + sizes[i].h == p.height;
    }
    EXPECT_TRUE(right && bottom) << padding;
  }
}

TEST(SkylinePack, LikeTilesFillASquareWithoutWaste) {
  const Packing p = pack_rects(std::vector<PackSize>(16, {10, 10}), {});
  EXPECT_EQ(p.width, 40);
  EXPECT_EQ(p.height, 40);
  const Packing padded = pack_rects(std::vector<PackSize>(16, {10, 10}), {.padding = 2});
  EXPECT_EQ(padded.width, 4 * 10 + 3 * 2);
  EXPECT_EQ(padded.height, 4 * 10 + 3 * 2);
}

TEST(SkylinePack, MixedSizesLeaveLittleGap) {
  const std::vector<PackSize> sizes = mixed_sizes();
  long long area = 0;
  for (const PackSize& s : sizes) area += static_cast<long long>(s.w) * s.h;
  const Packing p = pack_rects(sizes, {});
  const double filled = static_cast<double>(area) / (static_cast<double>(p.width) * p.height);
  std::printf("37 mixed rectangles fill %.3f of a %dx%d sheet\n", filled, p.width, p.height);
  EXPECT_GT(filled, 0.75);
}

TEST(SkylinePack, PowerOfTwoSidesAndTheSameAnswerEveryTime) {
  const std::vector<PackSize> sizes = mixed_sizes();
  const Packing p = pack_rects(sizes, {.padding = 1, .power_of_two = true});
  expect_apart_and_inside(sizes, p, 1);
  EXPECT_EQ(p.width & (p.width - 1), 0) << p.width;
  EXPECT_EQ(p.height & (p.height - 1), 0) << p.height;
  const Packing again = pack_rects(sizes, {.padding = 1, .power_of_two = true});
  ASSERT_EQ(again.places.size(), p.places.size());
  for (std::size_t i = 0; i < p.places.size(); ++i) {
    EXPECT_EQ(again.places[i].x, p.places[i].x);
    EXPECT_EQ(again.places[i].y, p.places[i].y);
  }
}

TEST(PackedSheet, EachFramePlacedAtItsSourceOffsetIsItsTile) {
  GridSheet grid = grid_sheet(4, 3, 32, 28, 2, {6});
  const image::Image unpacked = grid.image;
  const json unpacked_atlas = grid.atlas;
  pack_sheet(grid.image, grid.atlas, {.padding = 1});
  const json& meta = grid.atlas.at("meta");
  EXPECT_EQ(meta.at("size").at("w"), grid.image.width);
  EXPECT_EQ(meta.at("size").at("h"), grid.image.height);
  EXPECT_EQ(meta.at("packed"), true);
  EXPECT_FALSE(meta.contains("columns")) << "a packed sheet has no grid";
  EXPECT_LT(grid.image.width * grid.image.height, unpacked.width * unpacked.height / 4);
  for (const auto& [name, entry] : grid.atlas.at("frames").items()) {
    const json& before = unpacked_atlas.at("frames").at(name);
    EXPECT_EQ(visible(tile_of(grid.image, entry)), visible(tile_of(unpacked, before))) << "frame " << name;
    EXPECT_EQ(entry.at("trimmed"), true) << name;
    EXPECT_EQ(entry.at("sourceSize"), before.at("sourceSize"));
    EXPECT_EQ(entry.at("anchor"), before.at("anchor")) << "anchors stay fractions of the tile";
    EXPECT_EQ(entry.at("frame").at("w"), entry.at("spriteSourceSize").at("w"));
  }
  const json& empty = grid.atlas.at("frames").at("6");
  EXPECT_EQ(empty.at("frame").at("w"), 1) << "an empty tile keeps one transparent pixel";
  EXPECT_EQ(empty.at("frame").at("h"), 1);
  // The half-transparent corner pixel is kept, the colour without alpha not.
  EXPECT_EQ(grid.atlas.at("frames").at("0").at("frame").at("w"), 6 + 1);
}

TEST(PackedSheet, AnOpaqueTileIsNotTrimmed) {
  GridSheet grid = grid_sheet(2, 1, 20, 20, 0, {});
  for (std::size_t i = 3; i < grid.image.rgba.size(); i += 4) grid.image.rgba[i] = 255;
  pack_sheet(grid.image, grid.atlas, {});
  for (const auto& [name, entry] : grid.atlas.at("frames").items()) {
    EXPECT_EQ(entry.at("trimmed"), false) << name;
    EXPECT_EQ(entry.at("frame").at("w"), 20);
  }
}

// A lines layer over `grid`, laid out alike: in each tile a half-covered
// line pixel near its bottom-left corner, off the colour's block, and
// one in every tile, the ones with no colour too.
image::Image lines_over(const GridSheet& grid) {
  image::Image lines = blank(grid.image.width, grid.image.height);
  for (const auto& [name, entry] : grid.atlas.at("frames").items()) {
    const json& f = entry.at("frame");
    put(lines, f.at("x").get<int>() + 1, f.at("y").get<int>() + grid.tile_h - 2, 20, 10, 30, 160);
  }
  return lines;
}

TEST(PackedSheet, LayersAreCutToAllTheirPixelsAndPackAlike) {
  GridSheet grid = grid_sheet(4, 3, 32, 28, 2, {6});
  image::Image lines = lines_over(grid);
  const GridSheet unpacked = grid;
  const image::Image unpacked_lines = lines;
  GridSheet colour_alone = grid;
  pack_sheet(colour_alone.image, colour_alone.atlas, {.padding = 1});
  image::Image* const layers[] = {&grid.image, &lines};
  pack_sheet(layers, grid.atlas, {.padding = 1});
  EXPECT_EQ(lines.width, grid.image.width) << "one packed size for every layer";
  EXPECT_EQ(lines.height, grid.image.height);
  for (const auto& [name, entry] : grid.atlas.at("frames").items()) {
    const json& before = unpacked.atlas.at("frames").at(name);
    EXPECT_EQ(visible(tile_of(grid.image, entry)), visible(tile_of(unpacked.image, before))) << "colour " << name;
    EXPECT_EQ(visible(tile_of(lines, entry)), visible(tile_of(unpacked_lines, before))) << "lines " << name;
    if (name == "6") continue;  // no colour: below
    const json& own = colour_alone.atlas.at("frames").at(name).at("frame");
    EXPECT_GT(entry.at("frame").at("h"), own.at("h")) << name << ": the lines below the colour are kept";
  }
  const json& lines_only = grid.atlas.at("frames").at("6");
  EXPECT_EQ(lines_only.at("frame").at("w"), 1) << "a tile with lines alone keeps them";
  EXPECT_EQ(lines_only.at("spriteSourceSize").at("y"), grid.tile_h - 2);
}

TEST(AsepriteFile, ReadsBackFrameByFrameAsTheFormatLaysItOut) {
  const GridSheet grid = grid_sheet(4, 2, 32, 28, 2, {5});
  const std::string file = aseprite_file({{"color", &grid.image}}, grid.atlas);
  const AseRead ase = read_aseprite(file);
  EXPECT_EQ(ase.file_size, file.size());
  EXPECT_EQ(ase.frames, 8);
  EXPECT_EQ(ase.width, 32);
  EXPECT_EQ(ase.height, 28);
  EXPECT_EQ(ase.depth, 32);
  ASSERT_EQ(ase.chunk_types.size(), 8u);
  EXPECT_EQ(ase.chunk_types[0], (std::vector<int>{0x2007, 0x2019, 0x2018, 0x2020, 0x2020, 0x2004, 0x2022, 0x2005}));
  EXPECT_EQ(ase.chunk_types[5], std::vector<int>{}) << "an empty tile has no cel";
  std::vector<int> durations;
  for (const auto& [name, entry] : grid.atlas.at("frames").items()) durations.push_back(entry.at("duration"));
  EXPECT_EQ(ase.durations, durations);
  ASSERT_EQ(ase.tags.size(), 2u);
  EXPECT_EQ(ase.tags[0].name, "Walk_0");
  EXPECT_EQ(ase.tags[0].from, 0);
  EXPECT_EQ(ase.tags[0].to, 3);
  EXPECT_EQ(ase.tags[0].repeat, 0) << "a loop's repeat is not set";
  EXPECT_EQ(ase.tags[1].name, "Walk_90");
  EXPECT_EQ(ase.tags[1].from, 4);
  EXPECT_EQ(ase.tags[1].repeat, 1) << "a one-shot plays once";
  EXPECT_EQ(ase.layers, std::vector<std::string>{"color"});
  EXPECT_EQ(ase.pivot_keys, (std::vector<std::array<int, 3>>{{0, 16, 25}, {4, 16, 21}})) << "a key where it changes";
  ASSERT_EQ(ase.cels.size(), 7u);
  for (const AseRead::Cel& cel : ase.cels) {
    const image::Image canvas{32, 28, test::cel_on_canvas(cel, 32, 28)};
    const json& entry = grid.atlas.at("frames").at(std::to_string(cel.frame));
    EXPECT_EQ(visible(canvas), visible(tile_of(grid.image, entry))) << "frame " << cel.frame;
    EXPECT_LE(cel.w, 10) << "cut to its pixels";
  }
}

TEST(AsepriteFile, EachLayerHasItsCelsInEveryFrameItDraws) {
  const GridSheet grid = grid_sheet(4, 2, 32, 28, 2, {5});
  const image::Image lines = lines_over(grid);
  const std::vector<const image::Image*> sheets{&grid.image, &lines};
  const AseRead ase = read_aseprite(aseprite_file({{"color", &grid.image}, {"lines", &lines}}, grid.atlas));
  EXPECT_EQ(ase.layers, (std::vector<std::string>{"color", "lines"})) << "bottom first";
  std::vector<int> cels_per_layer(2, 0);
  for (const AseRead::Cel& cel : ase.cels) {
    ASSERT_LT(cel.layer, 2);
    ++cels_per_layer[static_cast<std::size_t>(cel.layer)];
    const image::Image canvas{32, 28, test::cel_on_canvas(cel, 32, 28)};
    const json& entry = grid.atlas.at("frames").at(std::to_string(cel.frame));
    EXPECT_EQ(visible(canvas), visible(tile_of(*sheets[static_cast<std::size_t>(cel.layer)], entry)))
        << "frame " << cel.frame << " layer " << cel.layer;
  }
  EXPECT_EQ(cels_per_layer, (std::vector<int>{7, 8})) << "the empty colour tile has lines";
}

TEST(AsepriteFile, APackedSheetGivesTheSameFile) {
  GridSheet grid = grid_sheet(4, 2, 32, 28, 2, {5});
  const std::string unpacked = aseprite_file({{"color", &grid.image}}, grid.atlas);
  pack_sheet(grid.image, grid.atlas, {.padding = 2, .power_of_two = true});
  EXPECT_EQ(aseprite_file({{"color", &grid.image}}, grid.atlas), unpacked);
}

TEST(GodotSpriteFrames, RegionsAreTheAtlasFramesAndAnimationsItsTags) {
  GridSheet grid = grid_sheet(3, 2, 32, 28, 0, {});
  pack_sheet(grid.image, grid.atlas, {});
  const std::string tres = godot_sprite_frames(grid.atlas, "res://sprites/walk.png");
  EXPECT_EQ(tres.rfind("[gd_resource type=\"SpriteFrames\" load_steps=8 format=3]\n", 0), 0u) << tres.substr(0, 80);
  EXPECT_NE(tres.find("[ext_resource type=\"Texture2D\" path=\"res://sprites/walk.png\" id=\"1_sheet\"]"),
            std::string::npos);
  for (const auto& [name, entry] : grid.atlas.at("frames").items()) {
    const json& f = entry.at("frame");
    const json& s = entry.at("spriteSourceSize");
    const std::string block =
        "[sub_resource type=\"AtlasTexture\" id=\"AtlasTexture_" + name +
        "\"]\natlas = ExtResource(\"1_sheet\")\nregion = Rect2(" + f.at("x").dump() + ", " + f.at("y").dump() + ", " +
        f.at("w").dump() + ", " + f.at("h").dump() + ")\nmargin = Rect2(" + s.at("x").dump() + ", " + s.at("y").dump() +
        ", " + std::to_string(32 - f.at("w").get<int>()) + ", " + std::to_string(28 - f.at("h").get<int>()) + ")\n";
    EXPECT_NE(tres.find(block), std::string::npos) << block;
  }
  const std::regex animation(
      R"re(\{\n"frames": \[([^\]]*)\],\n"loop": (true|false),\n"name": &"([^"]*)",\n"speed": ([0-9.]+)\n\})re");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(tres.begin(), tres.end(), animation); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    names.push_back(m[3]);
    EXPECT_EQ(m[2], names.size() == 2 ? "false" : "true") << "a one-shot's animation does not loop";
    const double speed = std::stod(m[4]);
    const std::string frames = m[1];
    const std::regex frame(R"re("duration": ([0-9.]+),\n"texture": SubResource\("AtlasTexture_([0-9]+)"\))re");
    int count = 0;
    for (auto f = std::sregex_iterator(frames.begin(), frames.end(), frame); f != std::sregex_iterator(); ++f) {
      const json& entry = grid.atlas.at("frames").at((*f)[2].str());
      EXPECT_NEAR(std::stod((*f)[1]) / speed * 1000, entry.at("duration").get<double>(), 1e-6);
      ++count;
    }
    EXPECT_EQ(count, 3);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"Walk_0", "Walk_90"}));
}

TEST(GodotSpriteFrames, AnUntrimmedFrameHasNoMarginAndNamesAreQuoted) {
  GridSheet grid = grid_sheet(2, 1, 20, 20, 0, {});
  grid.atlas["meta"]["frameTags"][0]["name"] = "Run \"fast\"\\1\n";
  const std::string tres = godot_sprite_frames(grid.atlas, "sheet.png");
  EXPECT_EQ(tres.find("margin ="), std::string::npos);
  EXPECT_NE(tres.find(R"("name": &"Run \"fast\"\\1\n",)"), std::string::npos) << tres;
  EXPECT_EQ(godot_quoted(std::string("a\x01z")), "\"a\\u0001z\"");
}

}  // namespace
}  // namespace toond::sheet_files
