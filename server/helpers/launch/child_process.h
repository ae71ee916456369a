#pragma once
// Runs a helper program on untrusted input with bounds on what it may cost
// the daemon: a wall-clock limit after which the helper (with its whole
// process group) is killed, a cap on what it may answer, and its input and
// output through socket pairs written with MSG_NOSIGNAL, so a helper that
// dies mid-conversation cannot raise SIGPIPE in the daemon. The helper
// sets its own memory and CPU limits before it reads its input.
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

namespace toond::scene {

struct ChildRun {
  std::string program;
  std::vector<std::string> arguments;  // after the program's own name
  std::string_view input;              // written to its standard input, then closed
  std::chrono::milliseconds time_limit{10000};
  std::size_t max_output = 1 << 20;  // bytes on standard output before it is killed
  std::size_t max_errors = 4096;     // bytes of standard error kept; more are read and dropped
};

struct ChildResult {
  enum class End { Exited, Signalled, TimedOut, OutputTooLarge, NotStarted };
  End end = End::NotStarted;
  int code = 0;  // exit status, signal number, or errno of the failed start
  std::string output;
  std::string errors;
};

// Never throws for what the child does; whatever happens, the child is
// gone (reaped) when this returns.
ChildResult run_child(const ChildRun& run);

}  // namespace toond::scene
