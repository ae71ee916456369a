#pragma once
// The file operations the store builds on, each one on disk when it
// returns: what a crash cannot undo once done. Failures throw
// std::system_error naming the path (for the log, never for a client).
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

namespace toond::scene {

// A file descriptor, closed when it goes.
class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  Fd(Fd&& other) noexcept : fd_(other.release()) {}
  Fd& operator=(Fd&& other) noexcept;
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd();
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

[[noreturn]] void throw_errno(const std::string& what, const std::filesystem::path& path, int error = errno);

// Syncs a folder, so that the entries created, renamed or removed in it
// stay so after a crash.
void fsync_dir(const std::filesystem::path& dir);

// Writes all of `bytes` at `offset`.
void write_all_at(int fd, std::string_view bytes, std::uint64_t offset, const std::filesystem::path& path);

// Creates the file (it must not exist), writes it whole and syncs it.
void write_file_durably(const std::filesystem::path& path, std::string_view bytes);

}  // namespace toond::scene
