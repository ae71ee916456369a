#pragma once
// A sprite sheet as one .aseprite file, the format Aseprite and LibreSprite
// save and the importers of Unity (com.unity.2d.aseprite), Bevy, LÖVE and
// MonoGame read, written as Aseprite's published file format lays it out
// (little-endian, a 128-byte header, then frames of chunks):
//  - the canvas is one tile (sourceSize), 32-bit RGBA, sRGB;
//  - a frame per atlas frame, in the atlas's order, each with its duration;
//  - a tag per atlas tag (from, to, loop direction, and its repeat count:
//    a one-shot's 1, a loop's 0, "not set"), each with a colour;
//  - a layer per image given, bottom first, and in each frame a cel per
//    layer cut to its visible pixels at their place in the tile,
//    zlib-compressed (no cel where a frame of a layer has none);
//  - a slice "pivot" over the whole canvas whose pivot is the atlas's
//    anchor in whole pixels, with a key wherever the anchor changes;
//  - a palette of the sheet's most used opaque colours, for touching up.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/image.h"

namespace toond::sheet_files {

struct AsepriteLayer {
  std::string name;
  const image::Image* sheet = nullptr;  // the sheet's image of this layer, laid out as the atlas says
};

// The most frames, and the widest or tallest canvas, the file can hold.
constexpr int kAsepriteMaxFrames = 65535;
constexpr int kAsepriteMaxSide = 32767;

// `atlas` is the sheet's (packed or not); every layer's image is laid out
// as it says. Throws std::invalid_argument past the limits above.
std::string aseprite_file(const std::vector<AsepriteLayer>& layers, const nlohmann::ordered_json& atlas);

}  // namespace toond::sheet_files
