#include "scene/store/folder_sweeper.h"

#include <sys/resource.h>
#include <unistd.h>

#include <system_error>
#include <utility>

namespace toond::scene {

FolderSweeper::FolderSweeper() : thread_([this] { run(); }) {}

FolderSweeper::~FolderSweeper() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void FolderSweeper::sweep(std::filesystem::path folder) {
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(std::move(folder));
  }
  wake_.notify_one();
}

void FolderSweeper::run() {
  // Deleting can wait; the upload that queued a folder should not. At its
  // own priority a woken sweeper would take the core from that upload.
  ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 10);
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, and nothing left
    const std::filesystem::path folder = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    // A folder a crash left half-deleted, or one gone meanwhile, is no error.
    std::error_code ec;
    std::filesystem::remove_all(folder, ec);
    lock.lock();
  }
}

}  // namespace toond::scene
