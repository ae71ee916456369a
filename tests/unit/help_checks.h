#pragma once
// What the --help tests of toond and toon share: the options a help text
// names, wherever it names them (option lists, synopses, prose).
#include <regex>
#include <set>
#include <string>

namespace toond::help_checks {

// Every word of `text` written as an option ("-o", "--set"), after a space,
// a bracket, a parenthesis or a bar; "--max-..." is a pattern, not a name.
inline std::set<std::string> options_named_in(const std::string& text) {
  static const std::regex option(R"((?:^|[\s\[(|])(--?[a-z](?:[a-z-]*[a-z])?)(?![-.a-z]))");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it) {
    names.insert((*it)[1].str());
  }
  return names;
}

}  // namespace toond::help_checks
