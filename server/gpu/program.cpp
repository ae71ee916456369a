#include "gpu/program.h"

#include <regex>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/gpu_error.h"
#include "gpu/shader_compile_error.h"
#include "gpu/shader_log.h"

namespace toond::gpu {
namespace {

// The file the log's first error lies in: a module's, when the error is in
// text an #include pasted in.
std::string file_of_first_error(const ShaderSource& source, const std::string& log) {
  const std::optional<int> number = first_shader_error(log).source;
  if (!number || *number <= 0 || static_cast<std::size_t>(*number) >= source.files.size()) return source.name;
  return source.files[static_cast<std::size_t>(*number)];
}

Shader compile_stage(GLenum stage, const ShaderSource& source, const std::vector<std::string>& defines) {
  Shader shader = Shader::create(stage);
  const std::string text = with_defines(source.text, defines);
  const char* ptr = text.c_str();
  glShaderSource(shader.id(), 1, &ptr, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader.id(), static_cast<GLsizei>(log.size()), nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    throw ShaderCompileError(file_of_first_error(source, log), log);
  }
  return shader;
}

GLenum stage_of(const std::string& name) {
  auto ends_with = [&](std::string_view suffix) {
    return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends_with(".vert")) return GL_VERTEX_SHADER;
  if (ends_with(".geom")) return GL_GEOMETRY_SHADER;
  if (ends_with(".frag")) return GL_FRAGMENT_SHADER;
  throw GpuError("shader file " + name + " has no stage extension (.vert, .geom, .frag)");
}

}  // namespace

std::string with_defines(std::string_view source, const std::vector<std::string>& defines) {
  std::size_t insert_at = 0;
  if (source.substr(0, 8) == "#version") {
    insert_at = source.find('\n');
    insert_at = insert_at == std::string_view::npos ? source.size() : insert_at + 1;
  }
  std::string out(source.substr(0, insert_at));
  for (const auto& d : defines) out += "#define " + d + "\n";
  // Keep the driver's line numbers equal to the file's own.
  out += "#line " + std::to_string(insert_at == 0 ? 1 : 2) + "\n";
  out += source.substr(insert_at);
  return out;
}

Program::Program(const ShaderSource& vertex, const ShaderSource& fragment, const std::vector<std::string>& defines)
    : Program(std::vector<ShaderSource>{vertex, fragment}, defines) {}

Program::Program(const std::vector<ShaderSource>& stages, const std::vector<std::string>& defines) {
  std::vector<Shader> shaders;
  std::string& names = names_;
  for (const ShaderSource& source : stages) {
    shaders.push_back(compile_stage(stage_of(source.name), source, defines));
    names += (names.empty() ? "" : " + ") + source.name;
    declared_.merge(declared_uniforms(source.text));
  }
  program_ = ProgramObject::create();
  for (const Shader& sh : shaders) glAttachShader(program_.id(), sh.id());
  glLinkProgram(program_.id());
  for (const Shader& sh : shaders) glDetachShader(program_.id(), sh.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program_.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program_.id(), static_cast<GLsizei>(log.size()), nullptr, log.data());
    throw ShaderCompileError(names, log);
  }
}

std::unordered_set<std::string> declared_uniforms(std::string_view source) {
  static const std::regex declaration(R"(\buniform\s+\w+\s+(\w+)\s*[\[;=])");
  std::unordered_set<std::string> names;
  const std::string text(source);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), declaration); it != std::sregex_iterator(); ++it) {
    names.insert((*it)[1].str());
  }
  return names;
}

GLint Program::location(std::string_view name) {
  auto it = locations_.find(std::string(name));
  if (it != locations_.end()) return it->second;
  const std::string key(name);
  if (!declared_.contains(key.substr(0, key.find('[')))) {
    throw GpuError("the program of " + names_ + " declares no uniform named " + key);
  }
  const GLint loc = glGetUniformLocation(program_.id(), key.c_str());
  locations_.emplace(key, loc);
  return loc;
}

void Program::set(std::string_view name, float v) { glProgramUniform1f(id(), location(name), v); }
void Program::set(std::string_view name, int v) { glProgramUniform1i(id(), location(name), v); }
void Program::set(std::string_view name, const glm::vec2& v) {
  glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::vec3& v) {
  glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::vec4& v) {
  glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::mat3& v) {
  glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::mat4& v) {
  glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set_array(std::string_view name, const std::vector<glm::vec2>& v) {
  if (v.empty()) return;
  glProgramUniform2fv(id(), location(name), static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}

void Program::set_array(std::string_view name, const std::vector<glm::vec3>& v) {
  if (v.empty()) return;
  glProgramUniform3fv(id(), location(name), static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}

void Program::set_array(std::string_view name, const std::vector<float>& v) {
  if (v.empty()) return;
  glProgramUniform1fv(id(), location(name), static_cast<GLsizei>(v.size()), v.data());
}
void Program::set_array(std::string_view name, const std::vector<int>& v) {
  if (v.empty()) return;
  glProgramUniform1iv(id(), location(name), static_cast<GLsizei>(v.size()), v.data());
}

}  // namespace toond::gpu
