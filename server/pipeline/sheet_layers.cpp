#include "pipeline/sheet_layers.h"

#include <algorithm>

namespace toond::pipeline {
namespace {

bool has_layer(const render::RenderParams& params, render::Output layer) {
  if (!params.sheet) return false;
  const std::vector<render::Output>& layers = params.sheet->layers;
  return std::find(layers.begin(), layers.end(), layer) != layers.end();
}

}  // namespace

std::vector<render::Output> drawn_layers(const render::RenderParams& params, SheetFile answer) {
  std::vector<render::Output> drawn{params.output};
  if (!params.sheet || (!params.sheet->pack && answer != SheetFile::Aseprite)) return drawn;
  for (const render::Output layer : params.sheet->layers) {
    if (layer != params.output) drawn.push_back(layer);
  }
  return drawn;
}

render::RenderParams layer_params(render::RenderParams frame, render::Output layer,
                                  const render::RenderParams& params) {
  frame.output = layer;
  if (layer == render::Output::Color && has_layer(params, render::Output::Lines)) {
    frame.outline.enabled = false;
    frame.contour.enabled = false;
  }
  return frame;
}

std::string layer_name(render::Output layer) { return layer == render::Output::Lines ? "lines" : "color"; }

}  // namespace toond::pipeline
