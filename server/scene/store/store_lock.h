#pragma once
// The store's one lock across replicas: an exclusive flock(2) on a file in
// the data directory that is never replaced, held for one pass over the
// store's index (an upload landing, the evictions it needs, a removal).
// The kernel lets it go when its holder dies, so a killed replica never
// leaves the store locked. A hung one that holds it would; a pass is a
// few file operations long, so waiting past StoreOptions::lock_wait gives
// up (StoreError::Kind::Busy) instead of hanging the upload with it.
//
// flock() locks an open file, not a process: two opens of the file in one
// process exclude each other too (two stores on one folder in a test are
// two replicas), while threads sharing one StoreLock must take turns by
// other means (the catalog's mutex).
#include <chrono>
#include <filesystem>

namespace toond::scene {

class StoreLock {
 public:
  // Opens (creating) the lock file; throws std::system_error when it cannot.
  explicit StoreLock(const std::filesystem::path& path);
  ~StoreLock();
  StoreLock(const StoreLock&) = delete;
  StoreLock& operator=(const StoreLock&) = delete;

  // Takes the lock, waiting at most `wait`; false when another holder kept
  // it all that time.
  bool lock(std::chrono::milliseconds wait);
  void unlock();

 private:
  int fd_ = -1;
};

}  // namespace toond::scene
