#include "render/frame/draw_pacing.h"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "render/plan/render_cost.h"

namespace toond::render {
namespace {

void draw_elements(GLenum mode, std::size_t index_count, std::size_t first_index) {
  glDrawElements(mode, static_cast<GLsizei>(index_count), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first_index * sizeof(std::uint32_t))));
}

// Crease edges a chunk: as many as cost what a band of the edge pass does;
// without bands, all of them.
std::size_t crease_chunk_indices(std::size_t band_texels) {
  if (band_texels == 0) return std::numeric_limits<std::size_t>::max();
  const double edges = static_cast<double>(band_texels) * kEdgeTexelSamples / kCreaseEdgeSamples;
  return 4 * std::max<std::size_t>(static_cast<std::size_t>(edges), 1);
}

}  // namespace

DrawPacing::DrawPacing(std::size_t chunk_triangles, std::size_t band_texels, Clock::time_point deadline,
                       std::function<void()> between_chunks)
    : chunk_indices_(std::max<std::size_t>(chunk_triangles, 1) * 3),
      band_texels_(band_texels),
      crease_chunk_indices_(crease_chunk_indices(band_texels)),
      deadline_(deadline),
      between_chunks_(std::move(between_chunks)) {}

void DrawPacing::draw_triangles(std::size_t index_count, std::size_t first_index) {
  draw_elements_in_chunks(GL_TRIANGLES, index_count, first_index, chunk_indices_, issued_);
}

void DrawPacing::draw_crease_edges(std::size_t index_count, std::size_t first_index) {
  draw_elements_in_chunks(GL_LINES_ADJACENCY, index_count, first_index, crease_chunk_indices_, crease_indices_issued_);
}

void DrawPacing::draw_elements_in_chunks(GLenum mode, std::size_t index_count, std::size_t first_index,
                                         std::size_t chunk, std::size_t& issued) {
  for (std::size_t done = 0; done < index_count && !expired_;) {
    if (Clock::now() > deadline_) {
      expired_ = true;
      return;
    }
    const std::size_t count = std::min(chunk - issued, index_count - done);
    draw_elements(mode, count, first_index + done);
    done += count;
    issued += count;
    if (issued < chunk) continue;
    issued = 0;
    end_chunk();
  }
}

void DrawPacing::draw_in_bands(int width, int height, double texels_per_pixel, const std::function<void()>& draw) {
  const double band_pixels = static_cast<double>(band_texels_) / std::max(texels_per_pixel, 1.0);
  const int rows =
      band_texels_ == 0 ? height : std::clamp(static_cast<int>(band_pixels / std::max(width, 1)), 1, height);
  if (rows >= height) {
    if (Clock::now() > deadline_) {
      expired_ = true;
      return;
    }
    draw();
    return;
  }
  // Each band is its own viewport: the full-screen triangle then covers
  // exactly its rows (a scissor box on a multisampled target let llvmpipe
  // draw the row below a band's once more, blending the line twice), and
  // gl_FragCoord stays the target's.
  GLint viewport[4] = {0, 0, width, height};
  glGetIntegerv(GL_VIEWPORT, viewport);
  for (int y = 0; y < height && !expired_; y += rows) {
    if (Clock::now() > deadline_) {
      expired_ = true;
      break;
    }
    glViewport(viewport[0], viewport[1] + y, width, std::min(rows, height - y));
    draw();
    end_chunk();
  }
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

void DrawPacing::end_chunk() {
  ++chunks_;
  wait_for_chunk();
  if (between_chunks_ && !expired_) between_chunks_();
}

void DrawPacing::wait_for_chunk() {
  const gpu::Fence drawn;
  if (drawn.get() == nullptr) {
    glFinish();
    return;
  }
  const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline_ - Clock::now());
  // The flush bit sends the chunk to the driver, so it draws while this
  // thread waits.
  const GLenum status =
      left.count() > 0 ? glClientWaitSync(drawn.get(), GL_SYNC_FLUSH_COMMANDS_BIT, static_cast<GLuint64>(left.count()))
                       : GL_TIMEOUT_EXPIRED;
  if (status == GL_TIMEOUT_EXPIRED || status == GL_WAIT_FAILED || Clock::now() > deadline_) expired_ = true;
}

void draw_triangles(DrawPacing* pacing, std::size_t index_count, std::size_t first_index) {
  if (pacing != nullptr) {
    pacing->draw_triangles(index_count, first_index);
  } else {
    draw_elements(GL_TRIANGLES, index_count, first_index);
  }
}

void draw_crease_edges(DrawPacing* pacing, std::size_t index_count, std::size_t first_index) {
  if (pacing != nullptr) {
    pacing->draw_crease_edges(index_count, first_index);
  } else {
    draw_elements(GL_LINES_ADJACENCY, index_count, first_index);
  }
}

void draw_full_screen(DrawPacing* pacing, int width, int height, double texels_per_pixel,
                      const std::function<void()>& draw) {
  if (pacing != nullptr) {
    pacing->draw_in_bands(width, height, texels_per_pixel, draw);
  } else {
    draw();
  }
}

}  // namespace toond::render
