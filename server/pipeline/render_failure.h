#pragma once
// A render that failed on the render threads' side, said in the pipeline's
// words. The entry (render_entry.h) turns the render threads' and the GPU's
// exceptions into this one type, so that whoever answers the request (the
// HTTP layer) words it without knowing the GPU. Its what() is the
// original's.
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace toond::pipeline {

class RenderFailure : public std::runtime_error {
 public:
  enum class Kind {
    DeadlineExceeded,  // the render's deadline passed while it waited in the queue
    Aborted,           // a paced render was stopped at its deadline between chunks
    QueueFull,         // its lane of the queue was full
    ShaderError,       // a shader (edited under --shader-dir) does not compile or link
    GpuReset,          // the GL context was lost; the render threads make a new one
    GpuError,          // any other failure of EGL or GL
  };
  // What a shader that does not compile says: its file, the driver's whole
  // log, and the log's first error with its line in that file when known.
  struct Shader {
    std::string file;
    std::string log;
    std::string first_error;
    std::optional<int> line;
  };

  RenderFailure(Kind kind, const std::string& what, Shader shader = {})
      : std::runtime_error(what), kind_(kind), shader_(std::move(shader)) {}

  Kind kind() const { return kind_; }
  const Shader& shader() const { return shader_; }

 private:
  Kind kind_;
  Shader shader_;
};

// Throws `error` again: as a RenderFailure when it is one of the render
// threads' or the GPU's, as itself otherwise.
[[noreturn]] void rethrow_as_render_failure(const std::exception_ptr& error);

}  // namespace toond::pipeline
