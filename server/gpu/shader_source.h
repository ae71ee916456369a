#pragma once
// Where GLSL text comes from. The daemon normally compiles the sources
// embedded at build time, which never change; with --shader-dir it reads
// them from a folder and notices edits, for look development.
#include <sys/types.h>
#include <ctime>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace toond::gpu {

class ShaderSources {
 public:
  virtual ~ShaderSources() = default;
  // The text of a shader file ("toon.frag"). Throws GpuError (a
  // ShaderCompileError naming the file, for files on disk) when there is none.
  virtual std::string read(const std::string& name) = 0;
  // Whether texts can change while the daemon runs. When false, changed()
  // is never worth calling and nothing is stat()ed.
  virtual bool can_change() const { return false; }
  // The files read so far whose content now differs from what read() last
  // returned for them (or that appeared or went away). Does not update that
  // record: read() does.
  virtual std::vector<std::string> changed() { return {}; }
};

// Texts that are fixed for the life of the process (the embedded shaders).
class FixedShaderSources final : public ShaderSources {
 public:
  using Lookup = std::function<std::string(const std::string& name)>;
  explicit FixedShaderSources(Lookup lookup) : lookup_(std::move(lookup)) {}
  std::string read(const std::string& name) override { return lookup_(name); }

 private:
  Lookup lookup_;
};

// Shader files in a folder: `name` is read from DIR/name, every time it is
// asked for; a file missing there is an error naming it (there is no
// fallback to the embedded text, so what renders is what is on disk).
//
// changed() first compares stat() data (device, inode, size, mtime, ctime,
// to the nanosecond), so an unchanged folder costs one stat() per file. A
// file whose timestamps are within two seconds of when it was last read is
// compared by content instead, so two writes within one timestamp tick of a
// coarse file system (or a write that keeps size and mtime) are not missed.
class ShaderDirectory final : public ShaderSources {
 public:
  // Throws std::invalid_argument when `dir` is not a directory.
  explicit ShaderDirectory(std::filesystem::path dir);

  std::string read(const std::string& name) override;
  bool can_change() const override { return true; }
  std::vector<std::string> changed() override;

  const std::filesystem::path& dir() const { return dir_; }

 private:
  struct Stamp {
    bool exists = false;
    dev_t dev = 0;
    ino_t ino = 0;
    off_t size = 0;
    std::timespec mtime{};
    std::timespec ctime{};
    bool operator==(const Stamp& o) const;
  };
  struct Seen {
    Stamp stamp;                      // taken just before the text was read
    std::optional<std::string> text;  // empty: the file could not be read
    std::timespec checked{};          // when the text was last read or confirmed
  };
  std::filesystem::path path_of(const std::string& name) const;
  static Stamp stamp_of(const std::filesystem::path& path);
  static bool racy(const Seen& seen);

  std::filesystem::path dir_;
  std::map<std::string, Seen> seen_;
};

}  // namespace toond::gpu
