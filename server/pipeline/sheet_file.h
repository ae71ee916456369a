#pragma once
// Which of a sheet's files a request asks for (?atlas=…): its image (PNG,
// or WebP with animate), its atlas alone (JSON), one .aseprite file, or a
// Godot 4 SpriteFrames resource. The stage that writes them is
// sheet_answer.h's.
#include <string>

namespace toond::pipeline {

enum class SheetFile { Image, AtlasJson, Aseprite, Godot };

struct SheetAnswer {
  SheetFile file = SheetFile::Image;
  // ?texture: the sheet's PNG as the Godot resource names it, a res://
  // path or one relative to the .tres; empty: the atlas's meta.image,
  // beside the .tres.
  std::string godot_texture;
};

}  // namespace toond::pipeline
