#pragma once
// One thread kept for CPU work a frame can hand off while the render thread
// records its passes (the hull cull, render/hull_cull.h). A thread started
// per frame would cost its start and, worse, fresh pages for its buffers
// every time; this one keeps both. Jobs run one at a time, in order. No GL.
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

namespace toond::render {

class BackgroundThread {
 public:
  BackgroundThread();
  ~BackgroundThread();
  BackgroundThread(const BackgroundThread&) = delete;
  BackgroundThread& operator=(const BackgroundThread&) = delete;

  // Runs `job` on the thread; the future holds its result or its exception.
  template <class Result>
  std::future<Result> run(std::function<Result()> job) {
    auto task = std::make_shared<std::packaged_task<Result()>>(std::move(job));
    std::future<Result> result = task->get_future();
    post([task] { (*task)(); });
    return result;
  }

 private:
  void post(std::function<void()> job);
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace toond::render
