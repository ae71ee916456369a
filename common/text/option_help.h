#pragma once
// How toond and toon lay out the option lists of their --help: each option
// as it is written ("-o, --output FILE"), its help in a column after the
// longest of them, and the help's further lines under its first.
#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace toond::text {

struct OptionHelp {
  std::string_view alias;  // "-o", or empty
  std::string_view name;   // "--output"
  std::string_view value;  // "FILE"; empty for a switch
  std::string_view help;   // a '\n' starts a line set under the first

  // As --help writes it, e.g. "-o, --output FILE".
  std::string written() const {
    std::string s(alias);
    if (!s.empty()) s += ", ";
    s += name;
    if (!value.empty()) s.append(" ").append(value);
    return s;
  }
};

// The column that clears the longest of `options`, written from `indent`,
// by one space.
inline std::size_t help_column(std::span<const OptionHelp> options, std::size_t indent) {
  std::size_t longest = 0;
  for (const OptionHelp& option : options) longest = std::max(longest, option.written().size());
  return indent + longest + 1;
}

// The option's lines, from `indent`, with its help from `column` on (one
// space after the option at least).
inline std::string option_lines(const OptionHelp& option, std::size_t indent, std::size_t column) {
  std::string out(indent, ' ');
  out += option.written();
  out.append(std::max<std::size_t>(column > out.size() ? column - out.size() : 0, 1), ' ');
  std::string_view help = option.help;
  for (std::size_t eol; (eol = help.find('\n')) != std::string_view::npos; help.remove_prefix(eol + 1)) {
    out.append(help.substr(0, eol)).append("\n").append(column, ' ');
  }
  return out.append(help).append("\n");
}

}  // namespace toond::text
