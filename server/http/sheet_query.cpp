#include "http/sheet_query.h"

#include <algorithm>

#include "request_error.h"

namespace toond::http {
namespace {

pipeline::SheetFile file_named(const std::string& name) {
  if (name == "json") return pipeline::SheetFile::AtlasJson;
  if (name == "aseprite") return pipeline::SheetFile::Aseprite;
  if (name == "godot") return pipeline::SheetFile::Godot;
  throw RequestError(400, "invalid_parameter",
                     "?atlas: json (the sheet's atlas alone), aseprite (one .aseprite file) or godot (a Godot 4 "
                     "SpriteFrames resource), not '" +
                         name.substr(0, 64) + "'",
                     "?atlas");
}

// A res:// or user:// path, or one relative to the resource (Godot finds
// it beside the .tres).
bool godot_path(const std::string& path) {
  if (path.empty() || path.size() > 1024) return false;
  if (std::any_of(path.begin(), path.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; })) {
    return false;
  }
  if (path.starts_with("res://") || path.starts_with("user://")) return path.size() > path.find("//") + 2;
  return path.front() != '/' && path.find(':') == std::string::npos && path.find('\\') == std::string::npos;
}

}  // namespace

pipeline::SheetAnswer sheet_answer_of(const httplib::Request& req) {
  pipeline::SheetAnswer answer;
  if (req.has_param("atlas")) answer.file = file_named(req.get_param_value("atlas"));
  if (!req.has_param("texture")) return answer;
  if (answer.file != pipeline::SheetFile::Godot) {
    throw RequestError(400, "invalid_parameter", "?texture: the sheet's PNG as ?atlas=godot names it; add ?atlas=godot",
                       "?texture");
  }
  answer.godot_texture = req.get_param_value("texture");
  if (!godot_path(answer.godot_texture)) {
    throw RequestError(400, "invalid_parameter",
                       "?texture: a res:// path (res://sprites/walk.png) or one relative to the .tres (walk.png), "
                       "at most 1024 bytes",
                       "?texture");
  }
  return answer;
}

}  // namespace toond::http
