#include "scene/store/model_use.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace toond::scene {
namespace fs = std::filesystem;

std::timespec wall_clock_now() {
  std::timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return now;
}

void stamp_use(const fs::path& model_dir) { stamp_use(model_dir, wall_clock_now()); }

void stamp_use(const fs::path& model_dir, const std::timespec& when) {
  const std::timespec times[2] = {when, when};
  // Setting a given time needs the folder's owner; a replica running as
  // another user may still set "now" as the file system's clock has it.
  if (::utimensat(AT_FDCWD, model_dir.c_str(), times, 0) != 0 && errno == EPERM) {
    ::utimensat(AT_FDCWD, model_dir.c_str(), nullptr, 0);
  }
}

void take_lease(const fs::path& model_dir, const std::string& holder) {
  const fs::path folder = model_dir / kLeaseFolder;
  const fs::path file = folder / holder;
  // Models stored before leases existed have no lease folder; mkdir fails
  // when the model itself has gone, so a removed model never comes back as
  // an empty folder.
  int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0 && errno == ENOENT && ::mkdir(folder.c_str(), 0755) == 0) {
    fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  }
  if (fd < 0) return;
  ::futimens(fd, nullptr);  // a renewed lease is as fresh as a new one
  ::close(fd);
}

void drop_lease(const fs::path& model_dir, const std::string& holder) {
  ::unlink((model_dir / kLeaseFolder / holder).c_str());
}

bool leased(const fs::path& model_dir, std::chrono::seconds expiry, const std::timespec& now) {
  const fs::path folder = model_dir / kLeaseFolder;
  DIR* dir = ::opendir(folder.c_str());
  if (!dir) return false;
  bool live = false;
  while (const dirent* entry = ::readdir(dir)) {
    const std::string name = entry->d_name;
    if (name == "." || name == "..") continue;
    struct stat st {};
    if (::stat((folder / name).c_str(), &st) != 0) continue;  // dropped meanwhile
    if (now.tv_sec - st.st_mtim.tv_sec < expiry.count()) {
      live = true;
      break;
    }
  }
  ::closedir(dir);
  return live;
}

}  // namespace toond::scene
