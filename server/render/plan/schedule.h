#pragma once
// When and how a queued frame is drawn, decided by its request's price
// before it is queued (pipeline/price.h) and carried with the job as one
// value: every frame of a sheet has its request's.
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace toond::render {

// A frame priced as long is drawn in chunks, its deadline checked between
// them (draw_pacing.h).
struct Pacing {
  // Nonzero: the meshes are drawn in chunks of this many triangles and the
  // render is stopped at its deadline (RenderAborted).
  std::size_t chunk_triangles = 0;
  // With it, the edge pass is drawn in bands of rows reading about this
  // many texels each, a chunk's worth.
  std::size_t band_texels = 0;
  bool paced() const { return chunk_triangles > 0; }
};

struct Schedule {
  // Who asked (the HTTP client's address): clients take turns in the queue.
  std::string client{};
  // The whole request's predicted cost in Msamples (render_cost.h): which
  // lane it waits in.
  double cost = 0;
  Pacing pacing{};
  // Unset: none. A job still queued when its deadline passes is skipped
  // (its future throws DeadlineExceeded); one already drawing finishes,
  // unless it is paced.
  std::optional<std::chrono::steady_clock::time_point> deadline{};
};

}  // namespace toond::render
