#include "sheet_files/atlas_view.h"

#include <stdexcept>

namespace toond::sheet_files {
namespace {

using json = nlohmann::ordered_json;

const json& field(const json& object, const char* name) {
  const auto found = object.find(name);
  if (found == object.end()) throw std::invalid_argument(std::string("atlas: no `") + name + "`");
  return *found;
}

int integer(const json& object, const char* name) {
  const json& value = field(object, name);
  if (!value.is_number_integer()) throw std::invalid_argument(std::string("atlas: `") + name + "` is not an integer");
  return value.get<int>();
}

PixelRect rect_of(const json& rect) {
  return {integer(rect, "x"), integer(rect, "y"), integer(rect, "w"), integer(rect, "h")};
}

AtlasFrame frame_of(const std::string& name, const json& entry) {
  AtlasFrame frame;
  frame.name = name;
  frame.frame = rect_of(field(entry, "frame"));
  frame.source = rect_of(field(entry, "spriteSourceSize"));
  const json& size = field(entry, "sourceSize");
  frame.tile_w = integer(size, "w");
  frame.tile_h = integer(size, "h");
  frame.duration_ms = integer(entry, "duration");
  const json& anchor = field(entry, "anchor");
  frame.anchor_x = field(anchor, "x").get<double>();
  frame.anchor_y = field(anchor, "y").get<double>();
  return frame;
}

AtlasTag tag_of(const json& entry) {
  AtlasTag tag;
  tag.name = field(entry, "name").get<std::string>();
  tag.from = integer(entry, "from");
  tag.to = integer(entry, "to");
  tag.direction = field(entry, "direction").get<std::string>();
  // Aseprite writes its count of plays as a string, and only when set.
  if (entry.contains("repeat")) tag.repeat = std::stoi(entry.at("repeat").get<std::string>());
  return tag;
}

}  // namespace

AtlasView view_of(const nlohmann::ordered_json& atlas) {
  AtlasView view;
  for (const auto& [name, entry] : field(atlas, "frames").items()) view.frames.push_back(frame_of(name, entry));
  for (const json& entry : field(field(atlas, "meta"), "frameTags")) view.tags.push_back(tag_of(entry));
  return view;
}

}  // namespace toond::sheet_files
