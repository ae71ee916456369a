// The kept background thread and the jobs handed to it, which the caller
// runs itself where the thread has not finished them.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <thread>

#include "render/cull/background_thread.h"

namespace toond::render {
namespace {

using namespace std::chrono_literals;

// Keeps the thread busy until released, so what is queued behind it waits.
struct Blocker {
  std::promise<void> release;
  std::atomic<bool> running{false};
  void block(BackgroundThread& thread) {
    thread.post([this, released = release.get_future().share()] {
      running = true;
      released.wait();
    });
    while (!running) std::this_thread::sleep_for(1ms);
  }
};

TEST(BackgroundThread, RunsJobsInOrder) {
  BackgroundThread thread;
  std::vector<int> order;
  for (int i = 0; i < 5; ++i) thread.post([&order, i] { order.push_back(i); });
  thread.drain();
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(BackgroundThread, DrainReturnsOnceEveryQueuedJobHasRun) {
  BackgroundThread thread;
  std::atomic<int> ran{0};
  for (int i = 0; i < 3; ++i) {
    thread.post([&ran] {
      std::this_thread::sleep_for(5ms);
      ++ran;
    });
  }
  thread.drain();
  EXPECT_EQ(ran, 3);
}

TEST(Handoff, TheCallerRunsAJobTheThreadHasNotBegun) {
  BackgroundThread thread;
  Blocker blocker;
  blocker.block(thread);
  std::atomic<int> runs{0};
  const std::thread::id caller = std::this_thread::get_id();
  Handoff<std::thread::id> job(thread, [&runs] {
    ++runs;
    return std::this_thread::get_id();
  });
  EXPECT_EQ(job.take(), caller);
  blocker.release.set_value();
  // The thread, once free, finds the job taken and skips it.
  thread.drain();
  EXPECT_EQ(runs, 1);
}

TEST(Handoff, TheThreadsResultIsTakenOnceItHasEnded) {
  BackgroundThread thread;
  std::atomic<int> runs{0};
  Handoff<std::thread::id> job(thread, [&runs] {
    ++runs;
    return std::this_thread::get_id();
  });
  thread.drain();
  EXPECT_NE(job.take(), std::this_thread::get_id());
  EXPECT_EQ(runs, 1);
}

TEST(Handoff, AJobTheThreadIsRunningIsWaitedForNotRunAgain) {
  BackgroundThread thread;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<bool> started{false};
  std::atomic<int> runs{0};
  Handoff<int> job(thread, [&, released] {
    const int run = ++runs;
    started = true;
    released.wait();  // the thread's run stalls, as behind a busy rasterizer
    return run;
  });
  while (!started) std::this_thread::sleep_for(1ms);
  std::future<int> taken = std::async(std::launch::async, [&job] { return job.take(); });
  EXPECT_EQ(taken.wait_for(50ms), std::future_status::timeout) << "the caller waits for the thread's run";
  release.set_value();
  EXPECT_EQ(taken.get(), 1);
  thread.drain();
  EXPECT_EQ(runs, 1);
}

TEST(Handoff, AnExceptionReachesTheCaller) {
  BackgroundThread thread;
  Handoff<int> job(thread, []() -> int { throw std::runtime_error("no"); });
  thread.drain();
  EXPECT_THROW(job.take(), std::runtime_error);
}

TEST(Handoff, AJobDroppedBeforeItBeganIsSkipped) {
  BackgroundThread thread;
  Blocker blocker;
  blocker.block(thread);
  std::atomic<int> runs{0};
  {
    Handoff<int> job(thread, [&runs] { return ++runs; });
  }
  blocker.release.set_value();
  thread.drain();
  EXPECT_EQ(runs, 0);
}

}  // namespace
}  // namespace toond::render
