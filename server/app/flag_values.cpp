#include "app/flag_values.h"

#include <cstdlib>
#include <stdexcept>

namespace toond::app {

unsigned long long parse_count(const std::string& flag, const std::string& text, unsigned long long min,
                               unsigned long long max) {
  std::size_t used = 0;
  unsigned long long v = 0;
  try {
    if (!text.empty() && text[0] != '-') v = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || v < min || v > max) {
    throw std::invalid_argument(flag + " expects an integer in " + std::to_string(min) + ".." + std::to_string(max) +
                                ", got '" + text + "'");
  }
  return v;
}

double parse_seconds(const std::string& flag, const std::string& text, double min, double max) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(v >= min && v <= max)) {
    throw std::invalid_argument(flag + " expects seconds in " + std::to_string(min).substr(0, 5) + ".." +
                                std::to_string(static_cast<long long>(max)) + ", got '" + text + "'");
  }
  return v;
}

const std::string& non_empty(const std::string& flag, const std::string& text, const char* what) {
  if (text.empty()) throw std::invalid_argument(flag + " needs " + what);
  return text;
}

}  // namespace toond::app
