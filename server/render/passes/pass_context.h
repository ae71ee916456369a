#pragma once
// What a pass draws with: the frame worked out before the first pass, the
// objects' GPU copies, its uniform blocks, the programs, the kept GL
// objects, the frame's target and its pacing. Render thread only.
#include <optional>
#include <vector>

#include "gpu/gl_object.h"
#include "gpu/program_cache.h"
#include "gpu/render_target.h"
#include "render/cull/background_thread.h"
#include "render/cull/hull_cull.h"
#include "render/frame/draw_pacing.h"
#include "render/frame/frame_blocks.h"
#include "render/frame/frame_context.h"
#include "render/frame/frame_resources.h"
#include "render/frame/render_object.h"

namespace toond::render {

struct PassContext {
  const FrameContext& frame;
  const std::vector<RenderObject>& objects;  // in the frame's order
  const FrameBlocks& blocks;
  gpu::ProgramCache& programs;
  FrameResources& resources;
  // The colour target; null for a data layer, which draws into the float
  // target of FrameResources::normal_depth_for and needs no colour.
  gpu::RenderTarget* target;
  // Where the frame's draws go in chunks that check its deadline; null:
  // drawn at once (draw_pacing.h).
  DrawPacing* pacing = nullptr;
  // The main pass's cap checks (object_draw.h), read once the image is back
  // (when their answers are ready anyway) to report which objects drew both
  // sides.
  std::vector<gpu::Query> main_cap_checks{};
  // Whether the hull leaves out the faces that cannot show (render/cull/hull_cull.h).
  bool cull_hull = false;
  // Whether the main pass leaves out runs of faces that surely turn to the
  // side it culls (render/cull/facing_runs.h).
  bool skip_turned_away_runs = true;
  // Whether crease lines may be drawn as wide GL lines (crease.geom's
  // WIDE_LINES) where the driver draws them that wide; else as quads.
  bool wide_lines = true;
  // Where work is handed off while the passes record (the hull cull).
  BackgroundThread& background;
  // Started before the first pass (start_hull_cull), taken by the hull pass.
  Handoff<std::vector<std::optional<HullSubset>>> hull_cull{};
  std::size_t hull_faces_culled = 0;  // reported in RenderOutput
  std::size_t hull_faces_turned_away = 0;
  std::size_t main_triangles_skipped = 0;
  std::size_t crease_edges_drawn = 0;
  std::size_t intersection_segments_drawn = 0;

  // Object i's GPU copy.
  const GpuModel& model(std::size_t i) const { return objects[i].gpu; }
};

}  // namespace toond::render
