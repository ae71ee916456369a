#include "helpers/process/resource_limits.h"

#include <sys/resource.h>

#include <charconv>

namespace toond::helper_process {
namespace {

void set_limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit limit{soft, hard};
  setrlimit(resource, &limit);
}

}  // namespace

void apply_resource_limits(const ResourceLimits& limits) {
  set_limit(RLIMIT_CORE, 0, 0);
  // Past the soft limit SIGXCPU ends the process; the hard one is a backstop.
  set_limit(RLIMIT_CPU, limits.cpu_seconds, limits.cpu_seconds + 1);
#if !defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of address space for its shadow, so
  // a sanitizer build runs without this one (the daemon's wall-clock limit
  // and output cap still hold, and __asan_default_options below bounds each
  // allocation).
  const rlim_t bytes = static_cast<rlim_t>(limits.memory_mb) << 20;
  set_limit(RLIMIT_AS, bytes, bytes);
#endif
}

std::optional<unsigned long long> parse_count(std::string_view text) {
  unsigned long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

}  // namespace toond::helper_process

#if defined(__SANITIZE_ADDRESS__)
// A helper under AddressSanitizer has no RLIMIT_AS, so a file claiming four
// billion vertices would have the reader construct them all (48 GB written)
// before the wall-clock kill. With each allocation bounded, such a request
// ends the helper at once with the sanitizer's report, which the daemon
// answers as the 422 it gives any crash of a helper. Read by the sanitizer
// runtime at start-up; ASAN_OPTIONS from the environment still override.
extern "C" const char* __asan_default_options() { return "max_allocation_size_mb=2048:abort_on_error=1"; }
#endif
