#pragma once
// Programs compiled once per variant and kept: the key is the stage files
// plus the sorted #defines, so a request that needs the same features as an
// earlier one reuses its program.
//
// With sources that can change (--shader-dir), refresh() between renders
// recompiles the programs whose files were edited. An edit that does not
// compile leaves every cached program (and the text new variants are built
// from) as it was, so the last good shaders keep serving.
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/program.h"
#include "gpu/shader_includes.h"
#include "gpu/shader_source.h"

namespace toond::gpu {

class ProgramCache {
 public:
  // Returns the GLSL text of a shader file; throws GpuError when missing.
  // Texts from a lookup are taken as fixed: refresh() does nothing.
  using SourceLookup = std::function<std::string(const std::string& name)>;
  explicit ProgramCache(SourceLookup lookup);
  explicit ProgramCache(std::unique_ptr<ShaderSources> sources);

  // Throws ShaderCompileError (a GpuError) when the variant does not build.
  Program& get(const std::string& vertex, const std::string& fragment, std::vector<std::string> defines);
  // The same for any set of stage files (e.g. with a geometry shader).
  Program& get(const std::vector<std::string>& stages, std::vector<std::string> defines);

  struct Reload {
    std::vector<std::string> files;  // the edited files now in use
    std::size_t programs = 0;        // programs rebuilt from them
  };
  // Render thread, between renders (it may replace programs that get()
  // returned). Returns at once, touching no file, when the sources cannot
  // change. Otherwise asks them which files changed; when one did, rebuilds
  // every cached program that uses an edited file (a stage or a module it
  // includes) and swaps them all in only
  // if all of them build. If one does not (or a file cannot be read), the
  // cache stays as it was and its ShaderCompileError is thrown, once: later
  // calls do not try again until a file changes again.
  Reload refresh();

  std::size_t size() const { return programs_.size(); }
  void clear();

 private:
  struct Entry {
    std::vector<std::string> stages;  // file names
    std::vector<std::string> files;   // the stages and every module they include
    std::vector<std::string> defines;
    std::unique_ptr<Program> program;
  };
  struct Built {
    std::unique_ptr<Program> program;
    std::vector<std::string> files;
  };
  // Expands each stage's includes with texts from `read`, then compiles.
  static Built build(const std::vector<std::string>& stages, const std::vector<std::string>& defines,
                     const ShaderTextReader& read);
  struct DiskText {
    std::string text;
    std::exception_ptr error;  // set when the file could not be read
  };
  const std::string& text(const std::string& name);

  std::unique_ptr<ShaderSources> sources_;
  std::map<std::string, Entry> programs_;
  // The texts the cached programs were built from (and new variants are).
  std::map<std::string, std::string> live_;
  // The latest texts read from changing sources; differ from live_ while an
  // edit does not compile.
  std::map<std::string, DiskText> disk_;
};

}  // namespace toond::gpu
