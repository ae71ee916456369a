#include "render/draw_pacing.h"

#include <algorithm>
#include <cstdint>

namespace toond::render {
namespace {

thread_local DrawPacing* current_pacing = nullptr;

void draw_elements(std::size_t index_count, std::size_t first_index) {
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index_count), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first_index * sizeof(std::uint32_t))));
}

}  // namespace

DrawPacing::DrawPacing(std::size_t chunk_triangles, Clock::time_point deadline, std::function<void()> between_chunks)
    : chunk_indices_(std::max<std::size_t>(chunk_triangles, 1) * 3),
      deadline_(deadline),
      between_chunks_(std::move(between_chunks)) {}

void DrawPacing::draw_triangles(std::size_t index_count, std::size_t first_index) {
  for (std::size_t done = 0; done < index_count && !expired_;) {
    if (Clock::now() > deadline_) {
      expired_ = true;
      return;
    }
    const std::size_t count = std::min(chunk_indices_ - issued_, index_count - done);
    draw_elements(count, first_index + done);
    done += count;
    issued_ += count;
    if (issued_ < chunk_indices_) continue;
    issued_ = 0;
    ++chunks_;
    wait_for_chunk();
    if (between_chunks_ && !expired_) between_chunks_();
  }
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
  const GLenum status = left.count() > 0 ? glClientWaitSync(drawn.get(), GL_SYNC_FLUSH_COMMANDS_BIT,
                                                             static_cast<GLuint64>(left.count()))
                                         : GL_TIMEOUT_EXPIRED;
  if (status == GL_TIMEOUT_EXPIRED || status == GL_WAIT_FAILED || Clock::now() > deadline_) expired_ = true;
}

PacingScope::PacingScope(DrawPacing* pacing) : outer_(current_pacing) { current_pacing = pacing; }

PacingScope::~PacingScope() { current_pacing = outer_; }

void draw_triangles(std::size_t index_count, std::size_t first_index) {
  if (current_pacing != nullptr) {
    current_pacing->draw_triangles(index_count, first_index);
  } else {
    draw_elements(index_count, first_index);
  }
}

}  // namespace toond::render
