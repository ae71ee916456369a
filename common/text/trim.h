#pragma once
// The one rule for trimming text toond and toon read (OBJ, MTL and .m
// lines, driver logs, HTTP header lists, error answers): spaces, tabs,
// carriage returns and newlines at either end go.
#include <string_view>

namespace toond::text {

inline std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

}  // namespace toond::text
