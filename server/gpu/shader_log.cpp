#include "gpu/shader_log.h"
#include "text/trim.h"

#include <regex>
#include <vector>

namespace toond::gpu {
namespace {

struct Located {
  bool is_error = false;
  std::optional<int> source;
  std::optional<int> line;
  std::string text;
};

std::optional<int> to_line(const std::string& digits) {
  // Driver logs are short; a line number beyond int is not a line number.
  if (digits.empty() || digits.size() > 9) return std::nullopt;
  return std::stoi(digits);
}

std::optional<Located> parse_line(const std::string& line) {
  // Mesa: "0:12(5): error: text" (or "preprocessor error")
  static const std::regex mesa(R"(^(\d+):(\d+)\(\d+\):\s*(?:preprocessor\s+)?(error|warning)\s*:\s*(.*)$)",
                               std::regex::icase);
  // NVIDIA: "0(12) : error C0000: text" (the code is optional in older drivers)
  static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(error|warning)\s*(?:[A-Z]\d+)?\s*:\s*(.*)$)",
                                 std::regex::icase);
  // glslang / AMD / Intel: "ERROR: 0:12: text"
  static const std::regex glslang(R"(^(error|warning)\s*:\s*(\d+):(\d+)\s*:\s*(.*)$)", std::regex::icase);
  // Unlocated: "error: text" (Mesa's link errors)
  static const std::regex bare(R"(^(error|warning)\s*:\s*(.*)$)", std::regex::icase);

  std::smatch m;
  auto is_error = [](const std::string& kind) { return kind[0] == 'e' || kind[0] == 'E'; };
  if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia)) {
    return Located{is_error(m[3].str()), to_line(m[1].str()), to_line(m[2].str()), m[4].str()};
  }
  if (std::regex_match(line, m, glslang)) {
    return Located{is_error(m[1].str()), to_line(m[2].str()), to_line(m[3].str()), m[4].str()};
  }
  if (std::regex_match(line, m, bare)) {
    return Located{is_error(m[1].str()), std::nullopt, std::nullopt, m[2].str()};
  }
  return std::nullopt;
}

}  // namespace

ShaderLogError first_shader_error(std::string_view log) {
  std::optional<Located> first_warning;
  std::string first_text;
  std::size_t pos = 0;
  while (pos <= log.size()) {
    auto end = log.find('\n', pos);
    if (end == std::string_view::npos) end = log.size();
    const std::string line(text::trim(log.substr(pos, end - pos)));
    pos = end + 1;
    if (line.empty()) continue;
    if (first_text.empty()) first_text = line;
    auto located = parse_line(line);
    if (!located) continue;
    if (located->is_error) return {located->source, located->line, located->text};
    if (!first_warning) first_warning = std::move(located);
  }
  if (first_warning) return {first_warning->source, first_warning->line, first_warning->text};
  return {std::nullopt, std::nullopt, first_text};
}

}  // namespace toond::gpu
