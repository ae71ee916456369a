#pragma once
// What a render hands back: the image (or a data layer's values), how long
// each pass took, the plan it ran and the detail each object was drawn at.
#include <string>
#include <vector>

#include "image/float_image.h"
#include "image/image.h"
#include "render/frame/frame_context.h"
#include "render/frame/pass_timing.h"

namespace toond::render {

struct RenderOutput {
  image::Image image;  // empty for a data layer
  // A data layer's values (output depth, normal or id), turned into its
  // PNG by the caller, who knows what the ids stand for.
  image::FloatImage layer;
  // An animated sheet's frames, in the atlas's order, each tile-sized (no
  // sheet is laid out: the animation holds them one by one).
  std::vector<image::Image> frames;
  // A sheet drawn as several layers (sheet.layers): the sheets of the
  // layers after the first (which is `image`), laid out alike, in the
  // order they were drawn (pipeline/sheet_layers.h).
  std::vector<image::Image> other_layers;
  std::vector<PassTiming> timings;
  std::string plan;          // PassPlan::describe()
  std::vector<LodUse> lods;  // one per object, in order
  // Samples per pixel the target really has: `msaa` clamped to the
  // driver's GL_MAX_SAMPLES (llvmpipe: 4).
  int samples = 1;
  // The hull outline's faces left out as unable to show (render/cull/hull_cull.h).
  std::size_t hull_faces_culled = 0;
  // Of those kept, the faces set apart as sure to turn to the side the hull
  // pass culls: drawn only where that side is (render/cull/hull_cull.h).
  std::size_t hull_faces_turned_away = 0;
  // The main pass's triangles left out in runs that surely turn away from
  // the camera (render/cull/facing_runs.h).
  std::size_t main_triangles_skipped = 0;
  // The crease edges the crease pass drew, runs of them whose faces all
  // surely turn away left out (render/passes/crease_pass.cpp).
  std::size_t crease_edges_drawn = 0;
  // The segments where parts cross that it drew (scene/mesh/intersection_lines.h).
  std::size_t intersection_segments_drawn = 0;
};

}  // namespace toond::render
