#pragma once
// The tokens and numbers of the line-based formats toond reads itself (.m,
// ASCII STL, ASCII PLY): locale-independent, never throwing, and strict
// about what a number is.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace toond::scene {

// A space or a tab: what separates tokens.
inline bool is_blank(char c) { return c == ' ' || c == '\t'; }

// The tokens of `s` between spaces and tabs.
std::vector<std::string_view> split_blanks(std::string_view s);

// A decimal real, the whole token. Out-of-range values become infinity
// (rejected later with the vertex named) or zero (underflow), as strtod
// would give.
std::optional<double> parse_real(std::string_view s);

// A decimal integer, the whole token, with an optional sign.
std::optional<std::int64_t> parse_integer(std::string_view s);

}  // namespace toond::scene
