#pragma once
// GLSL has no #include; toond's shaders are split into modules (*.glsl)
// that stage files pull in with a line of their own:
//
//   #include "lighting.glsl"
//
// The text of each module replaces the line, wrapped in #line directives
// that number it as a source string of its own, so a driver's error names
// the module's own line and (through `files`) the module. A module is
// pasted once per stage however often it is asked for, so modules may
// include what they need without guards. Pure: no GL.
#include <functional>
#include <string>
#include <vector>

namespace toond::gpu {

struct ExpandedShader {
  std::string text;
  // The files pasted in, indexed by the source-string number their
  // #line directives give them: files[0] is the stage file itself.
  std::vector<std::string> files;
};

// Reads `name` and every module it includes through `read`, which throws
// (GpuError) for a file it does not have. Throws ShaderCompileError naming
// the including file and line for a malformed #include line or a module
// that cannot be read.
using ShaderTextReader = std::function<std::string(const std::string& name)>;
ExpandedShader expand_includes(const std::string& name, const ShaderTextReader& read);

}  // namespace toond::gpu
