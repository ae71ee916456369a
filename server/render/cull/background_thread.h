#pragma once
// One thread kept for CPU work a frame can hand off while the render thread
// records its passes (the hull cull, render/cull/hull_cull.h). A thread started
// per frame would cost its start and, worse, fresh pages for its buffers
// every time; this one keeps both. Jobs run one at a time, in order. No GL.
#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

namespace toond::render {

class BackgroundThread {
 public:
  BackgroundThread();
  ~BackgroundThread();
  BackgroundThread(const BackgroundThread&) = delete;
  BackgroundThread& operator=(const BackgroundThread&) = delete;

  // Queues `job` to run on the thread. It must not throw.
  void post(std::function<void()> job);
  // Returns once every job queued before it has run.
  void drain();

 private:
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread thread_;
};

// A job handed to the background thread for a result the caller needs
// later. Where the thread has not begun it by then, the caller runs it
// itself: a thread just woken waits behind busy ones (a CPU rasterizer's)
// for up to a scheduler tick (4 ms measured), several times what such a
// job takes. Where the thread is at it, the caller waits for it: running
// it a second time beside the first took both from the rasterizer's
// threads, and the frame got slower (the armadillo's at MSAA 1, 6.9 → 8.5
// ms). The job must only read what it captured, and own or share all of
// that (it may still run after the caller has gone on). Dropped untaken,
// a job not yet begun is skipped. Render thread only, but for the job
// itself.
template <class Result>
class Handoff {
 public:
  Handoff() = default;
  Handoff(BackgroundThread& thread, std::function<Result()> job) : state_(std::make_shared<State>(std::move(job))) {
    thread.post([state = state_] { state->run_there(); });
  }
  Handoff(Handoff&&) = default;
  Handoff& operator=(Handoff&&) = default;
  ~Handoff() {
    if (state_) state_->begun.store(true);
  }

  bool valid() const { return state_ != nullptr; }
  // The thread's result if it has one, else the job's run here.
  Result take() {
    const std::shared_ptr<State> state = std::move(state_);
    if (state->begun.exchange(true)) return state->result.get();  // done, or under way there
    return state->job();
  }

 private:
  struct State {
    explicit State(std::function<Result()> j) : job(std::move(j)), result(done.get_future()) {}
    void run_there() {
      if (begun.exchange(true)) return;
      try {
        done.set_value(job());
      } catch (...) {
        done.set_exception(std::current_exception());
      }
    }
    const std::function<Result()> job;
    std::atomic<bool> begun{false};
    std::promise<Result> done;
    std::future<Result> result;
  };
  std::shared_ptr<State> state_;
};

}  // namespace toond::render
