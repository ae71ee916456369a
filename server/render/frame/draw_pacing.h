#pragma once
// A render priced as long (render_cost.h) is drawn in chunks of triangles,
// and its full-screen edge pass in bands of rows, with the deadline checked
// between them: one draw call of sixty thousand frame-sized triangles (or
// one edge pass over 2048², half a second on llvmpipe) cannot be stopped
// once issued, a chunk of them ends soon. One chunk (or band) is in flight
// at a time: the next is issued once the last
// has been drawn, so a render past its deadline hands the render thread
// back within about one chunk's time, and between chunks the render can
// step aside for others (`between_chunks`): a CPU rasteriser such as
// llvmpipe draws every context's work on one set of threads, in the order
// it arrives, so a short render queued behind a long one's chunks waits for
// them. Draws after the deadline are skipped, not failed half-way: every
// pass still ends its queries and restores its state, and the renderer then
// throws RenderAborted instead of reading back. Render thread only.
#include <chrono>
#include <cstddef>
#include <functional>
#include <stdexcept>

#include "gpu/gl.h"
#include "gpu/gl_object.h"

namespace toond::render {

// Thrown by Renderer::render when its deadline passed while it drew.
class RenderAborted : public std::runtime_error {
 public:
  explicit RenderAborted(const std::string& what) : std::runtime_error(what) {}
};

class DrawPacing {
 public:
  using Clock = std::chrono::steady_clock;
  // `between_chunks`, when set, runs after each chunk has been drawn, before
  // the next is issued (the render service waits there while short renders
  // draw). A band of a full-screen pass reads about `band_texels` texels
  // (0: such passes are drawn whole).
  DrawPacing(std::size_t chunk_triangles, std::size_t band_texels, Clock::time_point deadline,
             std::function<void()> between_chunks = {});

  // glDrawElements of `index_count` indices (triangles) from index
  // `first_index` of the bound element buffer, chunk by chunk. A chunk is
  // counted across calls: a pass drawn as many short ranges (runs left out
  // between them) waits once per chunk's triangles, not once per range.
  void draw_triangles(std::size_t index_count, std::size_t first_index);
  // glDrawElements of `index_count` indices of crease edges
  // (GL_LINES_ADJACENCY, four an edge) from `first_index`, in chunks of
  // edges each worth about a band (kEdgeTexelSamples a texel against
  // kCreaseEdgeSamples an edge, render_cost.h), counted across calls
  // apart from the triangles.
  void draw_crease_edges(std::size_t index_count, std::size_t first_index);
  // `draw` (a full-screen pass over a target `width` × `height`, reading
  // `texels_per_pixel` texels a pixel) once per band of rows, each band its
  // own viewport, waited for like a chunk. The pass's pixels do not depend
  // on one another's output, so the bands give the same bytes as one draw.
  void draw_in_bands(int width, int height, double texels_per_pixel, const std::function<void()>& draw);
  bool expired() const { return expired_; }
  std::size_t chunks_drawn() const { return chunks_; }

 private:
  // Waits until the chunk just issued is drawn; marks the pacing expired
  // when the deadline passes first.
  void wait_for_chunk();

  // After a chunk or band was issued: waits for it, then steps aside.
  void end_chunk();

  // glDrawElements of `mode` primitives in chunks of `chunk` indices,
  // `issued` of them drawn since the last wait.
  void draw_elements_in_chunks(GLenum mode, std::size_t index_count, std::size_t first_index, std::size_t chunk,
                               std::size_t& issued);

  std::size_t chunk_indices_;
  std::size_t band_texels_;
  std::size_t crease_chunk_indices_;
  std::size_t issued_ = 0;  // indices drawn since the last wait
  std::size_t crease_indices_issued_ = 0;
  Clock::time_point deadline_;
  std::function<void()> between_chunks_;
  std::size_t chunks_ = 0;
  bool expired_ = false;
};

// What the meshes draw with: glDrawElements at once without a pacing
// (null), through the frame's pacing with one. The pacing comes with the
// frame (PassContext::pacing), from its job's schedule (schedule.h).
void draw_triangles(DrawPacing* pacing, std::size_t index_count, std::size_t first_index);
// What the crease pass draws its edges with (GL_LINES_ADJACENCY), the same
// way: at once without a pacing, through the frame's pacing with one.
void draw_crease_edges(DrawPacing* pacing, std::size_t index_count, std::size_t first_index);
// What full-screen passes that may take long draw with: `draw` once without
// a pacing, in bands with one (DrawPacing::draw_in_bands).
void draw_full_screen(DrawPacing* pacing, int width, int height, double texels_per_pixel,
                      const std::function<void()>& draw);

}  // namespace toond::render
