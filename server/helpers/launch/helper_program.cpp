#include "helpers/launch/helper_program.h"

#include <signal.h>
#include <string.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <system_error>

namespace toond::scene {
namespace {

std::string signal_name(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? "SIG" + std::string(abbreviation) : "signal " + std::to_string(signal);
}

std::string seconds_text(std::chrono::milliseconds time) {
  return std::to_string(time.count() / 1000) + "." + std::to_string(time.count() % 1000 / 100) + " s";
}

}  // namespace

std::filesystem::path helper_program(const char* environment_variable, std::string_view name) {
  if (const char* set = std::getenv(environment_variable); set && *set) return set;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return (error ? std::filesystem::path() : self.parent_path()) / name;
}

long long helper_cpu_seconds(std::chrono::milliseconds time_limit) {
  return std::max<long long>(1, (time_limit.count() + 999) / 1000);
}

std::string helper_reason(const std::string& errors) {
  std::string line = errors.substr(0, errors.find('\n')).substr(0, 200);
  std::replace_if(
      line.begin(), line.end(), [](char c) { return c < 0x20 || c > 0x7e; }, '?');
  return line.empty() ? "it gave no reason" : line;
}

ChildResult run_helper(const ChildRun& run, std::string_view helper, std::string_view too_large) {
  const std::string subject(helper);
  ChildResult result = run_child(run);
  switch (result.end) {
    case ChildResult::End::NotStarted: {
      // The answer names the program, not where the daemon looked for it:
      // that is the operator's to read, in the log.
      const std::string reason = std::error_code(result.code, std::generic_category()).message();
      std::cerr << "toond: " << subject << " " << run.program << " cannot be started (" << reason << ")\n";
      throw HelperError(subject + " " + std::filesystem::path(run.program).filename().string() +
                        " cannot be started (" + reason + ")");
    }
    case ChildResult::End::TimedOut:
      throw HelperError(subject + " took longer than " + seconds_text(run.time_limit) + " and was stopped");
    case ChildResult::End::OutputTooLarge:
      throw HelperError(subject + " " + std::string(too_large));
    case ChildResult::End::Signalled:
      if (result.code == SIGXCPU) {
        throw HelperError(subject + " used more than " + std::to_string(helper_cpu_seconds(run.time_limit)) +
                          " s of processor time and was stopped");
      }
      throw HelperError(subject + " crashed (" + signal_name(result.code) + ")");
    case ChildResult::End::Exited:
      if (result.code == 1) throw HelperError(helper_reason(result.errors));
      if (result.code != 0) {
        throw HelperError(subject + " stopped with status " + std::to_string(result.code) + ": " +
                          helper_reason(result.errors));
      }
      break;
  }
  return result;
}

}  // namespace toond::scene
