#include "gpu/shader_source.h"

#include <sys/stat.h>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "gpu/shader_compile_error.h"

namespace toond::gpu {
namespace {

std::timespec now() {
  std::timespec t{};
  clock_gettime(CLOCK_REALTIME, &t);
  return t;
}

bool same_time(const std::timespec& a, const std::timespec& b) {
  return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec;
}

// a - b in seconds.
double seconds_between(const std::timespec& a, const std::timespec& b) {
  return static_cast<double>(a.tv_sec - b.tv_sec) + static_cast<double>(a.tv_nsec - b.tv_nsec) * 1e-9;
}

// The file's bytes, or nothing (with errno's text in `why`) when it cannot be read.
std::optional<std::string> read_file(const std::filesystem::path& path, std::string* why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (why) *why = std::strerror(errno);
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    if (why) *why = "read error";
    return std::nullopt;
  }
  return std::move(text).str();
}

}  // namespace

bool ShaderDirectory::Stamp::operator==(const Stamp& o) const {
  if (exists != o.exists) return false;
  if (!exists) return true;
  return dev == o.dev && ino == o.ino && size == o.size && same_time(mtime, o.mtime) && same_time(ctime, o.ctime);
}

ShaderDirectory::ShaderDirectory(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir_, ec)) {
    throw std::invalid_argument("shader directory " + dir_.string() + " is not a directory");
  }
}

std::filesystem::path ShaderDirectory::path_of(const std::string& name) const {
  // Names come from the renderer ("toon.frag"), never from a request; still,
  // nothing outside the folder is ever read.
  const std::filesystem::path rel(name);
  bool confined = !name.empty() && rel.is_relative();
  for (const auto& part : rel) confined = confined && part != "..";
  if (!confined) throw ShaderCompileError(name, "not a file name inside the shader directory");
  return dir_ / rel;
}

ShaderDirectory::Stamp ShaderDirectory::stamp_of(const std::filesystem::path& path) {
  struct stat st {};
  Stamp s;
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return s;
  s.exists = true;
  s.dev = st.st_dev;
  s.ino = st.st_ino;
  s.size = st.st_size;
  s.mtime = st.st_mtim;
  s.ctime = st.st_ctim;
  return s;
}

bool ShaderDirectory::racy(const Seen& seen) {
  if (!seen.stamp.exists) return false;
  // A write in the same timestamp tick as the one we saw would leave the
  // stamp as it is; ticks are at most 2 s (FAT), usually 1 ns..10 ms.
  constexpr double kTick = 2.0;
  return seconds_between(seen.checked, seen.stamp.mtime) < kTick ||
         seconds_between(seen.checked, seen.stamp.ctime) < kTick;
}

std::string ShaderDirectory::read(const std::string& name) {
  const std::filesystem::path path = path_of(name);
  Seen seen;
  seen.stamp = stamp_of(path);
  std::string why = "not a regular file";
  if (seen.stamp.exists) seen.text = read_file(path, &why);
  seen.checked = now();
  seen_[name] = seen;
  // The name, not the path: the error goes out to the client that asked for the render.
  if (!seen.text) throw ShaderCompileError(name, "cannot read " + name + " in the shader directory: " + why);
  return *seen.text;
}

std::vector<std::string> ShaderDirectory::changed() {
  std::vector<std::string> out;
  for (auto& [name, seen] : seen_) {
    const std::filesystem::path path = path_of(name);
    const Stamp stamp = stamp_of(path);
    if (stamp == seen.stamp && !racy(seen)) continue;
    // Metadata moved (or is too fresh to trust): look at the content.
    std::optional<std::string> text;
    if (stamp.exists) text = read_file(path, nullptr);
    if (text == seen.text) {
      // Touched, or rewritten with the same bytes: nothing to do.
      seen.stamp = stamp;
      seen.checked = now();
      continue;
    }
    out.push_back(name);
  }
  return out;
}

}  // namespace toond::gpu
