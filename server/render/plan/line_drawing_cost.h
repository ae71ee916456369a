#pragma once
// The price of a vector line drawing (output svg, render/vector/line_drawing.h),
// before it is drawn: the triangles it places, faces and bins, and the
// edges it tests for visibility (crease edges and seams at the request's
// angle, and the silhouettes and open edges a mesh of that many triangles
// shows). In the same Msamples as a rasterised frame, so that one
// --max-render-cost bounds both; the weights were fitted to the drawing's
// time (bench/line_drawing.py).
#include <span>

#include "render/plan/render_cost.h"
#include "render/plan/render_params.h"
#include "scene/mesh/model.h"

namespace toond::render {

RenderCost line_drawing_cost(const RenderParams& params, std::span<const scene::Mesh* const> meshes);

}  // namespace toond::render
