#include "pipeline/sheet_checks.h"

#include <algorithm>
#include <string>

#include "render/plan/pass_plan.h"
#include "request_error.h"

namespace toond::pipeline {
namespace {

// sheet.layers draws colour and lines alike; the answer is one of them.
void check_sheet_layers(const render::SheetParams& sheet, render::Output output) {
  if (sheet.layers.empty()) return;
  if (output != render::Output::Color && output != render::Output::Lines) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/layers: layers are color and lines drawn alike; they need output color or lines (depth, "
                       "normal and id are data, svg is vector paths)",
                       "/sheet/layers");
  }
  if (std::find(sheet.layers.begin(), sheet.layers.end(), output) == sheet.layers.end()) {
    throw RequestError(400, "invalid_parameter",
                       std::string("/sheet/layers: the answer's output \"") +
                           (output == render::Output::Lines ? "lines" : "color") +
                           "\" must be one of the layers drawn; add it to sheet.layers or ask for another output",
                       "/sheet/layers");
  }
}

}  // namespace

void check_sheet_params(const render::RenderParams& params) {
  if (!params.sheet) return;
  check_sheet_layers(*params.sheet, params.output);
  // Depth, normals and ids are data, not pictures: a palette would change
  // their values and WebP holds 8-bit colour, not 16-bit depth or an index.
  if (render::is_data_layer(params.output)) {
    if (params.sheet->pixel_art) {
      throw RequestError(400, "invalid_parameter",
                         "/sheet/pixel_art: pixel art needs output color or lines (depth, normal and id are data "
                         "a palette would change)",
                         "/sheet/pixel_art");
    }
    if (params.sheet->animate) {
      throw RequestError(400, "invalid_parameter",
                         "/sheet/animate: an animated WebP needs output color or lines (depth, normal and id "
                         "sheets come as PNG)",
                         "/sheet/animate");
    }
    if (params.sheet->pack) {
      throw RequestError(400, "invalid_parameter",
                         "/sheet/pack: a packed sheet needs output color or lines (a depth, normal or id tile has "
                         "no transparent pixels to trim)",
                         "/sheet/pack");
    }
  }
  if (params.sheet->pack && params.sheet->animate) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/pack: animate answers whole frames as an animated WebP; there is no sheet to pack",
                       "/sheet/pack");
  }
  if (!params.sheet->pixel_art) return;
  const int scale = params.sheet->pixel_art->scale;
  if (params.width % scale != 0 || params.height % scale != 0) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/pixel_art/scale: " + std::to_string(scale) + " must divide the tile size " +
                           std::to_string(params.width) + "×" + std::to_string(params.height) +
                           " (width and height) so every tile is whole art pixels",
                       "/sheet/pixel_art/scale");
  }
}

}  // namespace toond::pipeline
