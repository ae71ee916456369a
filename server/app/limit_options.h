#pragma once
// toond's flags for limits and access (--max-*, --token, --cors-origin),
// kept apart from the general ones in options.cpp.
#include <span>

#include "app/flag_table.h"
#include "http/access_control.h"

namespace toond::app {

// The --max-* flags, in --help's order.
std::span<const Flag> limit_flags();

// --token and --cors-origin.
std::span<const Flag> access_flags();

// TOOND_TOKEN sets the token when --token did not.
void apply_access_environment(http::AccessOptions& access);

}  // namespace toond::app
