#pragma once
// toond's flags for limits and access (--max-*, --token, --cors-origin):
// parsed here so options.cpp only delegates to them.
#include <cstddef>
#include <string>
#include <vector>

#include "http/access_control.h"
#include "http/request_limits.h"

namespace toond::app {

// When args[i] is one of these flags, reads it (and its value, advancing i)
// into `limits` / `access` and returns true; false for any other argument.
// Throws std::invalid_argument naming the flag for a bad value.
bool parse_limit_option(const std::vector<std::string>& args, std::size_t& i, http::RequestLimits& limits,
                        http::AccessOptions& access);

// The --help lines of these flags, with their defaults.
std::string limit_usage();

// TOOND_TOKEN sets the token when --token did not.
void apply_access_environment(http::AccessOptions& access);

}  // namespace toond::app
