#pragma once
// A sprite sheet's atlas as a Godot 4 SpriteFrames resource (a text
// resource, .tres, format 3), what an AnimatedSprite2D plays:
//  - the sheet's PNG as its one external Texture2D, at `texture_path`: a
//    res:// path, or a path relative to the .tres itself, which Godot
//    resolves beside it;
//  - an AtlasTexture per atlas frame: `region` its rectangle in the sheet,
//    and for a trimmed frame `margin` (where the rectangle lies in the
//    tile, and how much of the tile is left out) so that it keeps the
//    tile's size; `filter_clip` on, so that a filtered sprite never bleeds
//    a neighbour of the packed sheet; the anchor as metadata;
//  - an animation per atlas tag, its name the tag's, looping unless the
//    tag has a repeat count, `speed` the tag's mean frame rate and each
//    frame's `duration` its share of it, so that each frame shows for its
//    atlas duration (reverse and ping-pong tags are written out in the
//    order they play).
#include <string>

#include <nlohmann/json.hpp>

namespace toond::sheet_files {

std::string godot_sprite_frames(const nlohmann::ordered_json& atlas, const std::string& texture_path);

// A string as a Godot text resource quotes it: backslash, quote and control
// characters escaped, the rest UTF-8 as it is.
std::string godot_quoted(const std::string& text);

}  // namespace toond::sheet_files
