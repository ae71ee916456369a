#pragma once
// Rectangles packed into one small image: a skyline packer (each rectangle,
// tallest first, rests on the lowest stretch of the skyline it fits, then
// the leftmost) tried at a range of sheet widths, keeping the width whose
// sheet has the least area among those at most twice as long as wide (a
// long strip would have less, and outgrow the textures a GPU takes). Rectangles are never rotated: Phaser's and
// Godot's atlases cannot turn a frame back, and Aseprite never writes one
// turned.
#include <vector>

namespace toond::sheet_files {

struct PackSize {
  int w = 0;  // at least 1
  int h = 0;
};

struct PackOptions {
  int padding = 0;            // transparent pixels between neighbours, none around the edge
  bool power_of_two = false;  // the sheet's width and height each a power of two
};

struct PackPlace {
  int x = 0;
  int y = 0;
};

struct Packing {
  int width = 0;
  int height = 0;
  std::vector<PackPlace> places;  // the top left of each size, in the order given
};

// Deterministic: the same sizes and options always give the same packing.
Packing pack_rects(const std::vector<PackSize>& sizes, const PackOptions& options);

}  // namespace toond::sheet_files
