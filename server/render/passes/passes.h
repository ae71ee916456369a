#pragma once
// Every pass that draws, one function each, in the order a plan may run
// them (pass_plan.h). A new pass is a function here in its own file, a
// Pass value and its name (pass_plan), a line in `drawing_pass` and a line
// in plan_passes.
#include <optional>

#include "render/cull/facing_runs.h"
#include "render/passes/object_draw.h"
#include "render/passes/pass_context.h"
#include "render/plan/pass_plan.h"

namespace toond::render {

void draw_shadow_pass(PassContext& context);  // depth from the shadow-casting light
void draw_main_pass(PassContext& context);    // clears the target, shades, marks the stencil
void draw_floor_pass(PassContext& context);   // the ground plane, shaded like the model
void draw_hull_outline_pass(PassContext& context);
void draw_wireframe_pass(PassContext& context);
void draw_crease_pass(PassContext& context);   // crease lines along the crease edges
void draw_edge_prepass(PassContext& context);  // normals, distances and coverage per pixel
void draw_edge_pass(PassContext& context);
void draw_layer_pass(PassContext& context);       // depth, normal or id in place of the colour
void draw_downsample_pass(PassContext& context);  // supersampling's box filter into the output size

// Works out which side of each object's hull its draw skips and starts
// working out, off the render thread, which of the hull's faces may show
// (render/cull/hull_cull.h), for draw_hull_outline_pass to take; called before
// the first pass of a frame whose plan has the hull.
void start_hull_cull(PassContext& context);

// Where object i's runs of faces that surely turn away from the camera may
// be left out (render/cull/facing_runs.h), the camera seen from its mesh: the
// main pass culls the faces turned away (not an inside-out mesh's, which
// turn toward it), and the object is placed by a similarity. Else nullopt.
std::optional<MeshViewer> turned_away_runs_viewer(const PassContext& context, std::size_t i);

using DrawPass = void (*)(PassContext&);

// The function that draws `pass`; nullptr for the steps the renderer runs
// itself (resolve, readback, unpremultiply).
DrawPass drawing_pass(Pass pass);

}  // namespace toond::render
