#pragma once
// What `toon render -o FILE` asks the daemon for, by FILE's extension: a
// sheet's .aseprite file (.aseprite, .ase), its Godot SpriteFrames resource
// (.tres, with the sheet's PNG written beside it under the same name), its
// atlas alone (.json), or the image as it comes (anything else: a PNG, the
// WebP of sheet.animate, or the SVG of output svg). No network here: the unit tests check it.
#include <string>
#include <string_view>
#include <vector>

namespace toond::cli {

struct RenderAnswer {
  std::string query;                       // appended to the render route; "" for the image
  std::string what;                        // for messages: "an .aseprite file"
  std::vector<std::string> content_types;  // what the daemon may answer it with
  std::string companion_png;               // .tres: the sheet's PNG, written beside it; "" none
};

RenderAnswer render_answer_for(const std::string& output);

// A query parameter's value, percent-encoded (RFC 3986 unreserved kept).
std::string percent_encoded(std::string_view text);

}  // namespace toond::cli
