#pragma once
// Small helpers shared by the CLI's unit tests.
#include <string>

#include "cli_args.h"

namespace toond::cli::cli_test {

// The UsageError message `f` throws, or "" when it throws none.
template <typename F>
std::string usage_error(F&& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

}  // namespace toond::cli::cli_test
