#pragma once
// The atlas of a sprite sheet, in the JSON that Aseprite's "Export Sprite
// Sheet" writes (hash layout, TexturePacker's): `frames` named "0", "1", …
// with `frame`, `rotated`, `trimmed`, `spriteSourceSize`, `sourceSize` and
// `duration` (whole ms); `meta` with `app`, `version`, `image`, `format`,
// `size`, `scale` and `frameTags`. Phaser's aseprite loader and PixiJS's
// Spritesheet read it as it is: Phaser finds a tag's frames by their index
// as a string and reads `anchor` (or `pivot`); Pixi reads `anchor` and the
// top-level `animations` (tag name → frame names). toond's own keys ride
// beside them: each frame's yaw, pitch (and clip and time), and in `meta`
// the framing every frame shares, so that a single render can ask for the
// same view.
#include <string>

#include <nlohmann/json.hpp>

#include <span>

#include "render/plan/frame_plan.h"
#include "render/plan/render_params.h"
#include "render/plan/sheet_layout.h"

namespace toond::render {

// `params` are the sheet's render parameters, `plans` its frames' plans in
// layout order (their cameras and shared framing). Frames are named by their
// index in layout order, and listed in that order. A frame's anchor (and
// its `pivot`, the same point) is where the point under the orbit's
// centre, at the foot of the bounds, lands in its tile (0..1 from the top
// left): the spot a game stands the sprite on. One tag (and one Pixi
// animation) per clip, pitch and direction of an animated sheet (a
// one-shot clip's with Aseprite's "repeat": "1"), per pitch of a turntable.
nlohmann::ordered_json sheet_atlas(const SheetLayout& layout, const RenderParams& params,
                                   std::span<const FramePlan> plans, const std::string& image_name);

}  // namespace toond::render
