#pragma once
// Reading a GLSL compiler's info log: the first error and the line of the
// shader file it is on. Drivers write their logs differently:
//   Mesa:            0:12(5): error: syntax error, unexpected ';'
//   NVIDIA:          0(12) : error C0000: syntax error, unexpected ';'
//   glslang, AMD,
//   Intel (Windows): ERROR: 0:12: 'x' : undeclared identifier
// Programs are compiled from with_defines() text, whose #line directive keeps
// these numbers equal to the lines of the file on disk.
#include <optional>
#include <string>
#include <string_view>

namespace toond::gpu {

struct ShaderLogError {
  std::optional<int> line;  // 1-based line in the shader file, when the log gives one
  std::string text;         // the message, without the location prefix ("syntax error, …")
};

// The first error of `log` (a warning only when the log holds no error; the
// first non-empty line when nothing in it looks like a located message).
// Pure: no GL.
ShaderLogError first_shader_error(std::string_view log);

}  // namespace toond::gpu
