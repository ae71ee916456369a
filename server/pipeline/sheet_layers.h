#pragma once
// `sheet.layers`: a sheet's frames drawn as layers that line up, the colour
// without its lines and the lines alone, for an .aseprite file of them all
// (sheet_answer.h) and for packing, which trims each frame to the pixels of
// all its layers (sheet_files/packed_sheet.h) so that the colour and the
// lines sheet of one request pack alike. Each frame of each layer is a
// frame drawn: planned, priced, queued and assembled as one (plan.h,
// price.h, assemble.h), layer after layer.
#include <string>
#include <vector>

#include "pipeline/sheet_answer.h"
#include "render/plan/render_params.h"

namespace toond::pipeline {

// The layers a request draws, its output first, then the rest of
// sheet.layers in their order: all of them when the answer needs them all
// (an .aseprite file, or a packed sheet, whose trims are every layer's
// pixels), else the output alone, as for a request without layers.
std::vector<render::Output> drawn_layers(const render::RenderParams& params, SheetFile answer);

// A frame's parameters (of a request of `params`) as drawn in `layer`: that
// output, and for the colour, when the lines are a layer of their own, no
// outline and no contour.
render::RenderParams layer_params(render::RenderParams frame, render::Output layer, const render::RenderParams& params);

// "color" or "lines", as the schema and the .aseprite file name them.
std::string layer_name(render::Output layer);

}  // namespace toond::pipeline
