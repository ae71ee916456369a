#include "sheet_output.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace toond::cli {
namespace {

std::string lower_extension(const std::string& output) {
  std::string ext = std::filesystem::path(output).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

std::string percent_encoded(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += c;
    } else {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", u);
      out += escaped;
    }
  }
  return out;
}

RenderAnswer render_answer_for(const std::string& output) {
  const std::string ext = output == "-" ? "" : lower_extension(output);
  if (ext == ".aseprite" || ext == ".ase") {
    return {"?atlas=aseprite", "an .aseprite file", {"application/octet-stream"}, ""};
  }
  if (ext == ".json") return {"?atlas=json", "the sheet's atlas", {"application/json"}, ""};
  if (ext == ".tres") {
    // The resource names the PNG beside it by its file name, which Godot
    // resolves relative to the .tres.
    const std::string png = std::filesystem::path(output).replace_extension(".png").string();
    const std::string name = std::filesystem::path(png).filename().string();
    return {"?atlas=godot&texture=" + percent_encoded(name), "a Godot SpriteFrames resource", {"text/plain"}, png};
  }
  // The image as it comes: a PNG, sheet.animate's WebP, output svg's SVG
  // (which -o NAME.svg asks for, cli_args.h).
  return {"", "", {"image/png", "image/webp", "image/svg+xml"}, ""};
}

}  // namespace toond::cli
