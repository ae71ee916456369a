#include "render/frame/pass_timer.h"

namespace toond::render {

bool PassTimer::gpu_timers_available() {
  // One context per render thread, so the answer never changes for it.
  thread_local const bool available = [] {
    GLint bits = 0;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    glGetError();  // a driver without the query target flags an error here
    return bits > 0;
  }();
  return available;
}

PassTimer::PassTimer(std::vector<PassTiming>& out, bool gpu_timers) : out_(out) {
  if (gpu_timers && gpu_timers_available()) begin_query();
}

PassTimer::~PassTimer() {
  if (running_) glEndQuery(GL_TIME_ELAPSED);
}

void PassTimer::begin_query() {
  running_ = gpu::Query::create(GL_TIME_ELAPSED);
  glBeginQuery(GL_TIME_ELAPSED, running_.id());
}

void PassTimer::mark(Pass pass) {
  end_pass(pass);
  if (!running_) return;
  end_query();
  if (pass == Pass::Readback) {
    resolve_queries();
  } else {
    begin_query();
  }
}

void PassTimer::mark_in_flight(Pass pass) {
  end_pass(pass);
  if (running_) end_query();
}

void PassTimer::landed(double wait_ms) {
  if (!out_.empty()) {
    out_.back().cpu_ms += wait_ms;
    out_.back().ms += wait_ms;  // a GPU figure, where there is one, replaces it below
  }
  start_ = Clock::now();
  if (!ended_.empty()) resolve_queries();
}

void PassTimer::end_pass(Pass pass) {
  const auto now = Clock::now();
  const double cpu_ms = std::chrono::duration<double, std::milli>(now - start_).count();
  out_.push_back({pass_name(pass), cpu_ms, false, cpu_ms});
  start_ = now;
}

void PassTimer::end_query() {
  glEndQuery(GL_TIME_ELAPSED);
  ended_.emplace_back(std::move(running_), out_.size() - 1);
}

void PassTimer::resolve_queries() {
  std::vector<double> gpu_ms;
  for (const auto& [query, index] : ended_) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &ns);
    gpu_ms.push_back(static_cast<double>(ns) * 1e-6);
  }
  // No pass can take longer on the GPU than the whole render took on the
  // clock; llvmpipe's first query in a new context can report nonsense,
  // and then the wall-clock figures are the better answer.
  const double wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - first_start_).count();
  bool plausible = true;
  for (double ms : gpu_ms) plausible = plausible && ms <= wall_ms + 1.0;
  if (plausible) {
    for (std::size_t i = 0; i < ended_.size(); ++i) {
      PassTiming& t = out_[ended_[i].second];
      t.ms = gpu_ms[i];
      t.gpu = true;
    }
  }
  ended_.clear();
}

}  // namespace toond::render
