#pragma once
// What every helper program does first: bound its own memory and processor
// time, before it reads a byte of the untrusted input it is given, so a
// runaway parser ends in its own process with a signal the daemon reports.
#include <optional>
#include <string_view>

namespace toond::helper_process {

struct ResourceLimits {
  unsigned long long memory_mb = 0;
  unsigned long long cpu_seconds = 0;
};

// Applies the limits to this process; no core file is ever written.
// Past the processor limit the process gets SIGXCPU.
void apply_resource_limits(const ResourceLimits& limits);

// A decimal count as a flag's value ("512"), nullopt for anything else.
std::optional<unsigned long long> parse_count(std::string_view text);

}  // namespace toond::helper_process
