#pragma once
// Reading a GLSL compiler's info log: the first error and the line of the
// shader file it is on. Drivers write their logs differently:
//   Mesa:            0:12(5): error: syntax error, unexpected ';'
//   NVIDIA:          0(12) : error C0000: syntax error, unexpected ';'
//   glslang, AMD,
//   Intel (Windows): ERROR: 0:12: 'x' : undeclared identifier
// The first number is the source string: 0 for the stage file, the
// module's number for text pasted in by #include (gpu/shader_includes.h),
// whose #line directives keep the line equal to the line of that file.
#include <optional>
#include <string>
#include <string_view>

namespace toond::gpu {

struct ShaderLogError {
  std::optional<int> source;  // source-string number, when the log gives one
  std::optional<int> line;    // 1-based line in the shader file, when the log gives one
  std::string text;           // the message, without the location prefix ("syntax error, …")
};

// The first error of `log` (a warning only when the log holds no error; the
// first non-empty line when nothing in it looks like a located message).
// Pure: no GL.
ShaderLogError first_shader_error(std::string_view log);

}  // namespace toond::gpu
