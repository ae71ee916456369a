#include "gpu/shader_includes.h"

#include <algorithm>
#include <optional>
#include <string_view>

#include "gpu/shader_compile_error.h"

namespace toond::gpu {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view strip(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// An error at a line of the including file, written the way glslang
// writes its logs, so gpu/shader_log.h finds the line.
std::string located_error(int line_number, const std::string& text) {
  return "ERROR: 0:" + std::to_string(line_number) + ": " + text;
}

// The module a line asks for; nothing when the line is no #include.
// Throws when it is one but not of the form `#include "name"`.
std::optional<std::string> included_name(std::string_view line, const std::string& file, int line_number) {
  std::string_view rest = strip(line);
  if (!rest.starts_with('#')) return std::nullopt;
  rest = strip(rest.substr(1));
  if (!rest.starts_with("include")) return std::nullopt;
  rest = strip(rest.substr(7));
  const bool quoted =
      rest.size() >= 3 && rest.front() == '"' && rest.back() == '"' && rest.find('"', 1) == rest.size() - 1;
  if (!quoted) throw ShaderCompileError(file, located_error(line_number, "#include takes one quoted file name"));
  return std::string(rest.substr(1, rest.size() - 2));
}

class Expander {
 public:
  explicit Expander(const ShaderTextReader& read) : read_(read) {}

  ExpandedShader run(const std::string& name) {
    files_.push_back(name);
    paste(name, 0, read_(name));
    return {std::move(out_), std::move(files_)};
  }

 private:
  void paste(const std::string& file, int source_number, const std::string& text) {
    int line_number = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string::npos) end = text.size();
      const std::string_view line(text.data() + pos, end - pos);
      pos = end + 1;
      ++line_number;
      const std::optional<std::string> module = included_name(line, file, line_number);
      if (!module) {
        out_.append(line);
        out_ += '\n';
        continue;
      }
      include(*module, file, line_number);
      // Back in this file, numbered from the line after the #include.
      out_ += "#line " + std::to_string(line_number + 1) + " " + std::to_string(source_number) + "\n";
    }
  }

  void include(const std::string& module, const std::string& from, int line_number) {
    if (std::find(files_.begin(), files_.end(), module) != files_.end()) return;
    std::string text;
    try {
      text = read_(module);
    } catch (const ShaderCompileError& e) {
      throw ShaderCompileError(from, located_error(line_number, "#include \"" + module + "\": " + e.log()));
    } catch (const std::exception& e) {
      throw ShaderCompileError(from, located_error(line_number, "#include \"" + module + "\": " + e.what()));
    }
    const int number = static_cast<int>(files_.size());
    files_.push_back(module);
    out_ += "#line 1 " + std::to_string(number) + "\n";
    paste(module, number, text);
  }

  const ShaderTextReader& read_;
  std::string out_;
  std::vector<std::string> files_;
};

}  // namespace

ExpandedShader expand_includes(const std::string& name, const ShaderTextReader& read) {
  return Expander(read).run(name);
}

}  // namespace toond::gpu
