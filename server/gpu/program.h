#pragma once
// A linked GLSL program built from vertex + fragment (+ optional geometry)
// sources with feature #defines inserted after the #version line, the way
// shader variants are made: one source file, many programs.
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/gl_object.h"

namespace toond::gpu {

struct ShaderSource {
  std::string name;  // file name, for error messages
  std::string text;
  // The files a source-string number in the text's #line directives names
  // (gpu/shader_includes.h); empty: the text is all `name`'s.
  std::vector<std::string> files = {};
};

class Program {
 public:
  Program() = default;
  // Compiles and links. Throws ShaderCompileError with the file name and the
  // driver's log when a stage does not compile or the program does not link.
  Program(const ShaderSource& vertex, const ShaderSource& fragment, const std::vector<std::string>& defines);
  // Any set of stages; each stage is named by its file's extension (.vert,
  // .geom, .frag).
  Program(const std::vector<ShaderSource>& stages, const std::vector<std::string>& defines);

  GLuint id() const { return program_.id(); }
  void use() const { glUseProgram(program_.id()); }

  // Uniform setters look the location up once and remember it. A uniform
  // the sources declare but the compiler optimised away (a variant that
  // does not read it) is skipped; a name no source declares is a mistake
  // and throws GpuError, so a misspelt name fails the first render that
  // sets it rather than leaving a value at zero.
  void set(std::string_view name, float v);
  void set(std::string_view name, int v);
  void set(std::string_view name, const glm::vec2& v);
  void set(std::string_view name, const glm::vec3& v);
  void set(std::string_view name, const glm::vec4& v);
  void set(std::string_view name, const glm::mat3& v);
  void set(std::string_view name, const glm::mat4& v);
  void set_array(std::string_view name, const std::vector<glm::vec2>& v);
  void set_array(std::string_view name, const std::vector<glm::vec3>& v);
  void set_array(std::string_view name, const std::vector<float>& v);
  void set_array(std::string_view name, const std::vector<int>& v);

 private:
  GLint location(std::string_view name);

  ProgramObject program_;
  std::string names_;  // the stage files, for messages
  std::unordered_set<std::string> declared_;
  std::unordered_map<std::string, GLint> locations_;
};

// The names of the uniforms `source` declares outside blocks
// ("uniform vec3 u_x;" gives u_x; a block's members are not among them).
std::unordered_set<std::string> declared_uniforms(std::string_view source);

// Inserts `#define X` lines right after the source's #version line.
std::string with_defines(std::string_view source, const std::vector<std::string>& defines);

}  // namespace toond::gpu
