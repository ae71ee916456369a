#include "pipeline/sheet_answer.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "pipeline/encode.h"
#include "pipeline/request.h"
#include "pipeline/sheet_layers.h"
#include "render/plan/pass_plan.h"
#include "request_error.h"
#include "sheet_files/aseprite_file.h"
#include "sheet_files/godot_sprite_frames.h"
#include "sheet_files/packed_sheet.h"

namespace toond::pipeline {
namespace {

const char* query_of(SheetFile file) {
  switch (file) {
    case SheetFile::AtlasJson:
      return "?atlas=json";
    case SheetFile::Aseprite:
      return "?atlas=aseprite";
    case SheetFile::Godot:
      return "?atlas=godot";
    case SheetFile::Image:
      break;
  }
  return "";
}

void check_aseprite(const Request& request) {
  if (render::is_data_layer(request.params.output)) {
    throw RequestError(400, "invalid_parameter",
                       "/output: an .aseprite sheet holds RGBA colour, output color or lines (depth, normal and id "
                       "sheets come as PNG)",
                       "/output");
  }
  if (request.layout->frames.size() > static_cast<std::size_t>(sheet_files::kAsepriteMaxFrames)) {
    throw RequestError(422, "too_many_frames",
                       "/sheet: an .aseprite file holds at most 65535 frames; this sheet has " +
                           std::to_string(request.layout->frames.size()),
                       "/sheet");
  }
}

std::string texture_path(const Request& request, const nlohmann::ordered_json& atlas) {
  if (!request.answer.godot_texture.empty()) return request.answer.godot_texture;
  return atlas.at("meta").at("image").get<std::string>();
}

// The layers drawn (sheet_layers.h), colour below lines as a painter
// stacks them; Aseprite lists layers bottom first.
std::vector<sheet_files::AsepriteLayer> aseprite_layers(const render::RenderOutput& out, const Request& request) {
  const std::vector<render::Output> drawn = drawn_layers(request.params, request.answer.file);
  std::vector<sheet_files::AsepriteLayer> layers;
  for (const render::Output layer : {render::Output::Color, render::Output::Lines}) {
    const auto at = std::find(drawn.begin(), drawn.end(), layer);
    if (at == drawn.end()) continue;
    const std::size_t index = static_cast<std::size_t>(at - drawn.begin());
    layers.push_back({layer_name(layer), index == 0 ? &out.image : &out.other_layers[index - 1]});
  }
  return layers;
}

}  // namespace

void check_sheet_answer(const Request& request) {
  const SheetFile file = request.answer.file;
  if (file == SheetFile::Image) return;
  if (!request.layout) {
    throw RequestError(400, "invalid_parameter", std::string(query_of(file)) + " needs a `sheet` in the parameters",
                       "/sheet");
  }
  if (file == SheetFile::AtlasJson) return;
  if (request.params.sheet->animate) {
    throw RequestError(400, "invalid_parameter",
                       std::string("/sheet/animate: ") + query_of(file) +
                           " writes the sheet's frames from its PNG; animate answers a WebP instead",
                       "/sheet/animate");
  }
  if (file == SheetFile::Aseprite) check_aseprite(request);
}

bool needs_drawing(const Request& request) {
  switch (request.answer.file) {
    case SheetFile::Image:
    case SheetFile::Aseprite:
      return true;
    case SheetFile::AtlasJson:
    case SheetFile::Godot:
      break;
  }
  return request.params.sheet && request.params.sheet->pack;
}

void pack_sheet_output(render::RenderOutput& out, nlohmann::ordered_json& atlas, const Request& request) {
  const auto start = std::chrono::steady_clock::now();
  const render::SheetParams& sheet = *request.params.sheet;
  std::vector<image::Image*> layers{&out.image};
  for (image::Image& layer : out.other_layers) layers.push_back(&layer);
  sheet_files::pack_sheet(layers, atlas, {.padding = sheet.padding, .power_of_two = sheet.power_of_two});
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  out.timings.push_back({"pack", ms, false, ms});
}

Encoded encode_sheet_file(const render::RenderOutput* out, const Request& request,
                          const nlohmann::ordered_json& atlas) {
  Encoded encoded;
  switch (request.answer.file) {
    case SheetFile::AtlasJson:
      encoded.body = atlas.dump(2);
      encoded.content_type = "application/json";
      encoded.stage = "json";
      break;
    case SheetFile::Godot:
      encoded.body = sheet_files::godot_sprite_frames(atlas, texture_path(request, atlas));
      encoded.content_type = "text/plain; charset=utf-8";
      encoded.headers.emplace_back("Content-Disposition", "attachment; filename=\"sheet.tres\"");
      encoded.stage = "godot";
      break;
    case SheetFile::Aseprite:
      encoded.body = sheet_files::aseprite_file(aseprite_layers(*out, request), atlas);
      encoded.content_type = "application/octet-stream";
      encoded.headers.emplace_back("Content-Disposition", "attachment; filename=\"sheet.aseprite\"");
      encoded.stage = "aseprite";
      break;
    case SheetFile::Image:
      break;
  }
  return encoded;
}

}  // namespace toond::pipeline
