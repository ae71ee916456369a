#pragma once
// Running one of toond's helper programs (toond-draco-decode,
// toond-assimp-convert) on untrusted input and turning however it ended into
// its answer or one sentence: a crash, a hang, a runaway or garbage from the
// helper becomes a HelperError, never a crash of the daemon.
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "helpers/launch/child_process.h"

namespace toond::scene {

class HelperError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// $`environment_variable` when set, else `name` in the running executable's
// folder (where the build and the container image put the helpers beside
// toond).
std::filesystem::path helper_program(const char* environment_variable, std::string_view name);

// The processor seconds a helper may use within `time_limit` (at least 1).
long long helper_cpu_seconds(std::chrono::milliseconds time_limit);

// Runs `run` and returns how it ended when the helper exited with status 0
// (its answer on standard output, its notes on standard error). Otherwise throws HelperError saying what happened,
// with `helper` as the subject ("the decoder took longer than 10.0 s and
// was stopped"); status 1 is the helper's own refusal, whose first line of
// standard error is the message; `too_large` says why an over-long answer
// is wrong ("answered more than the primitive's accessors can hold").
ChildResult run_helper(const ChildRun& run, std::string_view helper, std::string_view too_large);

// The helper's first line of standard error, printable and at most 200 bytes.
std::string helper_reason(const std::string& errors);

}  // namespace toond::scene
