#pragma once
// A sheet's atlas (the JSON of render/atlas/sheet_atlas.h, the one every
// engine reads) as the few typed fields the sheet files are written from.
// The writers read the atlas rather than the layout, so that an .aseprite
// file or a Godot resource says exactly what the JSON says, packed or not.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace toond::sheet_files {

struct PixelRect {
  int x = 0;
  int y = 0;
  int w = 0;
  int h = 0;
};

struct AtlasFrame {
  std::string name;
  PixelRect frame;   // where its pixels are in the sheet's image
  PixelRect source;  // spriteSourceSize: where those pixels lie in the tile
  int tile_w = 0;    // sourceSize: the tile as drawn
  int tile_h = 0;
  int duration_ms = 0;
  double anchor_x = 0;  // 0..1 of the tile, from its top left
  double anchor_y = 0;
};

struct AtlasTag {
  std::string name;
  int from = 0;  // frame indices, inclusive
  int to = 0;
  std::string direction;  // Aseprite's: forward, reverse, pingpong, pingpong_reverse
  int repeat = 0;         // 0: not set (loops); n: plays n times
};

struct AtlasView {
  std::vector<AtlasFrame> frames;  // in the atlas's order, which is frame index order
  std::vector<AtlasTag> tags;
};

// Throws std::invalid_argument when a field the files need is missing or
// of the wrong type: the atlas is toond's own, so that is a bug, not bad
// input.
AtlasView view_of(const nlohmann::ordered_json& atlas);

}  // namespace toond::sheet_files
