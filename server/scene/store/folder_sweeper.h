#pragma once
// Deletes the folders of models already let go, on a thread of its own: a
// model leaves the store when its folder is renamed out of place, so the
// upload that let it go need not wait for its files to be deleted too.
// What is still queued when the store closes is deleted then; a crash
// leaves the renamed folders (`.tmp-removed-…`) to the next start's sweep.
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <thread>

namespace toond::scene {

class FolderSweeper {
 public:
  FolderSweeper();
  // Deletes what is queued, then stops.
  ~FolderSweeper();
  FolderSweeper(const FolderSweeper&) = delete;
  FolderSweeper& operator=(const FolderSweeper&) = delete;

  void sweep(std::filesystem::path folder);

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::filesystem::path> queue_;
  bool stopping_ = false;
  std::thread thread_;  // last: started once the rest exists
};

}  // namespace toond::scene
