#pragma once
#include <string>

#include "gpu/gpu_error.h"

namespace toond::gpu {

// A shader that does not compile or link: names the source file and keeps the
// driver's log (which carries the GLSL line numbers).
class ShaderCompileError : public GpuError {
 public:
  ShaderCompileError(std::string file, std::string log)
      : GpuError("shader " + file + " failed to compile:\n" + log), file_(std::move(file)), log_(std::move(log)) {}
  const std::string& file() const { return file_; }
  const std::string& log() const { return log_; }

 private:
  std::string file_;
  std::string log_;
};

}  // namespace toond::gpu
