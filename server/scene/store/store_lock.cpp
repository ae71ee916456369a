#include "scene/store/store_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>
#include <thread>

namespace toond::scene {

StoreLock::StoreLock(const std::filesystem::path& path)
    : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
  if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "cannot open " + path.string());
}

StoreLock::~StoreLock() { ::close(fd_); }

bool StoreLock::lock(std::chrono::milliseconds wait) {
  // flock() has no timeout: polling, from a tenth of a millisecond (a pass
  // is usually shorter than one) up to 2 ms between tries.
  const auto deadline = std::chrono::steady_clock::now() + wait;
  std::chrono::microseconds pause(100);
  while (true) {
    if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return true;
    if (errno != EWOULDBLOCK && errno != EINTR) {
      throw std::system_error(errno, std::generic_category(), "cannot lock the model store");
    }
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(pause);
    pause = std::min<std::chrono::microseconds>(pause * 2, std::chrono::milliseconds(2));
  }
}

void StoreLock::unlock() { ::flock(fd_, LOCK_UN); }

}  // namespace toond::scene
