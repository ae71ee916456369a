#include "parallel/parallel_tasks.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace toond::parallel {
namespace {

struct Job {
  Job(const std::function<void(int)>& t, int n, int helpers) : task(t), count(n), helper_slots(helpers) {}

  const std::function<void(int)>& task;
  const int count;
  std::atomic<int> next{0};
  std::atomic<int> helper_slots;
  std::mutex mutex;
  std::condition_variable all_done;
  int finished = 0;          // guarded by mutex
  std::exception_ptr error;  // the first one; guarded by mutex
};

// Runs the job's next task, if one is left. Once every index is taken this
// touches nothing but `next`, so a helper still holding a job whose caller
// has returned is harmless.
bool run_next(Job& job) {
  const int index = job.next.fetch_add(1);
  if (index >= job.count) return false;
  std::exception_ptr error;
  try {
    job.task(index);
  } catch (...) {
    error = std::current_exception();
  }
  std::lock_guard lock(job.mutex);
  if (error && !job.error) job.error = error;
  if (++job.finished == job.count) job.all_done.notify_all();
  return true;
}

class HelperPool {
 public:
  static HelperPool& instance() {
    static HelperPool pool;
    return pool;
  }
  int size() const { return static_cast<int>(threads_.size()); }

  void offer(const std::shared_ptr<Job>& job) {
    {
      std::lock_guard lock(mutex_);
      jobs_.push_back(job);
      queued_.store(static_cast<int>(jobs_.size()), std::memory_order_relaxed);
    }
    work_.notify_all();
  }

  void withdraw(const std::shared_ptr<Job>& job) {
    std::lock_guard lock(mutex_);
    const auto it = std::find(jobs_.begin(), jobs_.end(), job);
    if (it != jobs_.end()) jobs_.erase(it);
    queued_.store(static_cast<int>(jobs_.size()), std::memory_order_relaxed);
  }

 private:
  HelperPool() {
    for (int i = 1; i < hardware_threads(); ++i) threads_.emplace_back([this] { serve(); });
  }
  ~HelperPool() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    work_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

  void serve() {
    for (;;) {
      wait_briefly_for_work();
      std::shared_ptr<Job> job;
      {
        std::unique_lock lock(mutex_);
        work_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
        if (stopping_) return;
        job = jobs_.front();
        // The helper taking a job's last slot takes the job off the queue.
        if (job->helper_slots.fetch_sub(1) <= 1) jobs_.pop_front();
        queued_.store(static_cast<int>(jobs_.size()), std::memory_order_relaxed);
      }
      while (run_next(*job)) {
      }
    }
  }

  // An encode asks for help two or three times in quick succession
  // (palette; for truecolour the opacity check; deflate), and waking a
  // sleeping thread costs a large share of a small frame's encode on two
  // cores (toond_png_bench): a helper that just finished watches for the
  // next job a little while before it sleeps. Kept short, as the watching
  // takes a core from whatever else wants it.
  void wait_briefly_for_work() const {
    const auto until = std::chrono::steady_clock::now() + kWatchForWork;
    while (queued_.load(std::memory_order_relaxed) == 0 && std::chrono::steady_clock::now() < until) {
    }
  }
  static constexpr std::chrono::microseconds kWatchForWork{50};

  std::mutex mutex_;
  std::atomic<int> queued_{0};  // jobs_.size(), readable without the lock
  std::condition_variable work_;
  std::deque<std::shared_ptr<Job>> jobs_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace

int hardware_threads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

void run_tasks(int count, int threads, const std::function<void(int)>& task) {
  if (count <= 0) return;
  HelperPool& pool = HelperPool::instance();
  const int helpers = std::min({threads - 1, count - 1, pool.size()});
  if (helpers <= 0) {
    for (int i = 0; i < count; ++i) task(i);
    return;
  }
  const auto job = std::make_shared<Job>(task, count, helpers);
  pool.offer(job);
  while (run_next(*job)) {
  }
  pool.withdraw(job);
  std::unique_lock lock(job->mutex);
  job->all_done.wait(lock, [&] { return job->finished == job->count; });
  if (job->error) std::rethrow_exception(job->error);
}

}  // namespace toond::parallel
