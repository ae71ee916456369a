#pragma once
// Times each pass of a render: wall-clock time on the render thread, and,
// where the driver has timer queries (GL_TIME_ELAPSED) and a GPU to time,
// the time the GPU spent on the pass's commands. A pass starts where the previous one was
// marked. GPU figures are read back once the readback pass is marked (the
// readback waits for every earlier command, so they are ready then); passes
// after it are CPU work and keep their wall-clock time. Render thread only.
#include <chrono>
#include <utility>
#include <vector>

#include "gpu/gl_object.h"
#include "render/frame/pass_timing.h"
#include "render/plan/pass_plan.h"

namespace toond::render {

class PassTimer {
 public:
  // `gpu_timers`: count GPU time too (where the driver can).
  PassTimer(std::vector<PassTiming>& out, bool gpu_timers);
  ~PassTimer();  // ends a query still running (a render that threw)
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  void mark(Pass pass);
  // A frame kept in flight: marks its readback issued, without waiting for
  // the GPU's figures; landed() adds the wait for the pixels (measured by
  // the caller: the thread records another frame in between) and reads
  // them. Later marks count from landed().
  void mark_in_flight(Pass pass);
  void landed(double wait_ms);

  // Whether this driver counts GPU time (checked once per thread).
  static bool gpu_timers_available();

 private:
  using Clock = std::chrono::steady_clock;
  void end_pass(Pass pass);  // the entry for `pass`, wall time since the last mark
  void begin_query();
  void end_query();  // the running query, to be read for the last entry
  void resolve_queries();

  std::vector<PassTiming>& out_;
  const Clock::time_point first_start_ = Clock::now();
  Clock::time_point start_ = first_start_;
  gpu::Query running_;  // empty: not counting
  // Ended queries and the entry of `out_` each one times.
  std::vector<std::pair<gpu::Query, std::size_t>> ended_;
};

}  // namespace toond::render
