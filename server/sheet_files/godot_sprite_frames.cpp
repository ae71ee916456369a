#include "sheet_files/godot_sprite_frames.h"

#include <cstdio>
#include <sstream>
#include <vector>

#include "sheet_files/atlas_view.h"

namespace toond::sheet_files {
namespace {

// Godot reads a number with a point as a float; whole numbers keep ".0".
std::string godot_float(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", value);
  std::string s = text;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string rect2(int x, int y, int w, int h) {
  return "Rect2(" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(w) + ", " + std::to_string(h) +
         ")";
}

std::string atlas_texture_id(const AtlasFrame& frame) { return "AtlasTexture_" + frame.name; }

void write_atlas_texture(std::ostringstream& out, const AtlasFrame& frame) {
  out << "[sub_resource type=\"AtlasTexture\" id=" << godot_quoted(atlas_texture_id(frame)) << "]\n";
  out << "atlas = ExtResource(\"1_sheet\")\n";
  out << "region = " << rect2(frame.frame.x, frame.frame.y, frame.frame.w, frame.frame.h) << "\n";
  if (frame.frame.w != frame.tile_w || frame.frame.h != frame.tile_h) {
    out << "margin = "
        << rect2(frame.source.x, frame.source.y, frame.tile_w - frame.frame.w, frame.tile_h - frame.frame.h) << "\n";
  }
  out << "filter_clip = true\n";
  out << "metadata/anchor = Vector2(" << godot_float(frame.anchor_x) << ", " << godot_float(frame.anchor_y) << ")\n\n";
}

// The frames of a tag in the order they play once through.
std::vector<int> playing_order(const AtlasTag& tag) {
  std::vector<int> forward;
  for (int i = tag.from; i <= tag.to; ++i) forward.push_back(i);
  std::vector<int> backward(forward.rbegin(), forward.rend());
  const bool reversed = tag.direction == "reverse" || tag.direction == "pingpong_reverse";
  std::vector<int> order = reversed ? backward : forward;
  if (tag.direction == "pingpong" || tag.direction == "pingpong_reverse") {
    const std::vector<int>& back = reversed ? forward : backward;
    if (back.size() > 2) order.insert(order.end(), back.begin() + 1, back.end() - 1);
  }
  return order;
}

void write_animation(std::ostringstream& out, const AtlasTag& tag, const AtlasView& view) {
  const std::vector<int> order = playing_order(tag);
  double total_ms = 0;
  for (int i : order) total_ms += view.frames.at(static_cast<std::size_t>(i)).duration_ms;
  // Frames a second on average; a frame shows for duration / speed seconds.
  const double speed = total_ms > 0 ? order.size() * 1000.0 / total_ms : 1.0;
  out << "{\n\"frames\": [";
  for (std::size_t k = 0; k < order.size(); ++k) {
    const AtlasFrame& frame = view.frames.at(static_cast<std::size_t>(order[k]));
    out << (k ? ", {\n" : "{\n") << "\"duration\": " << godot_float(frame.duration_ms * speed / 1000.0) << ",\n"
        << "\"texture\": SubResource(" << godot_quoted(atlas_texture_id(frame)) << ")\n}";
  }
  out << "],\n\"loop\": " << (tag.repeat == 0 ? "true" : "false") << ",\n\"name\": &" << godot_quoted(tag.name)
      << ",\n\"speed\": " << godot_float(speed) << "\n}";
}

}  // namespace

std::string godot_quoted(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\t':
        quoted += "\\t";
        break;
      case '\r':
        quoted += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
          quoted += escaped;
        } else {
          quoted += c;
        }
    }
  }
  return quoted + "\"";
}

std::string godot_sprite_frames(const nlohmann::ordered_json& atlas, const std::string& texture_path) {
  const AtlasView view = view_of(atlas);
  std::ostringstream out;
  // load_steps: the resources the file holds, and the file itself.
  out << "[gd_resource type=\"SpriteFrames\" load_steps=" << view.frames.size() + 2 << " format=3]\n\n";
  out << "[ext_resource type=\"Texture2D\" path=" << godot_quoted(texture_path) << " id=\"1_sheet\"]\n\n";
  for (const AtlasFrame& frame : view.frames) write_atlas_texture(out, frame);
  out << "[resource]\nanimations = [";
  for (std::size_t t = 0; t < view.tags.size(); ++t) {
    if (t) out << ", ";
    write_animation(out, view.tags[t], view);
  }
  out << "]\n";
  return out.str();
}

}  // namespace toond::sheet_files
