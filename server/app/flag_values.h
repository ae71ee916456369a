#pragma once
// The values toond's flags take, read strictly: all of the text or a
// std::invalid_argument naming the flag.
#include <string>

namespace toond::app {

// A whole number in min..max.
unsigned long long parse_count(const std::string& flag, const std::string& text, unsigned long long min,
                               unsigned long long max);

// Seconds in min..max, fractions allowed.
double parse_seconds(const std::string& flag, const std::string& text, double min, double max);

// `text` itself, which must not be empty: "--token needs <what>" otherwise.
const std::string& non_empty(const std::string& flag, const std::string& text, const char* what);

}  // namespace toond::app
