// Running a helper program with bounds: whatever it does (exits, crashes,
// hangs, floods its output, stops reading its input), run_child comes back
// in time with the child gone, and the Draco helper keeps to its memory
// limit.
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <string>

#include "helpers/launch/child_process.h"

namespace toond::scene {
namespace {

using namespace std::chrono_literals;
using End = ChildResult::End;

ChildResult shell(const std::string& script, std::string_view input = {}, std::chrono::milliseconds time_limit = 10s,
                  std::size_t max_output = 1 << 20) {
  ChildRun run;
  run.program = "/bin/sh";
  run.arguments = {"-c", script};
  run.input = input;
  run.time_limit = time_limit;
  run.max_output = max_output;
  return run_child(run);
}

TEST(ChildProcess, InputGoesInAndOutputComesBack) {
  const std::string input(3 << 20, 'x');  // more than a socket buffer holds
  const ChildResult r = shell("cat; echo oops >&2; exit 3", input, 10s, 4 << 20);
  EXPECT_EQ(r.end, End::Exited);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.output, input);
  EXPECT_EQ(r.errors, "oops\n");
}

TEST(ChildProcess, AChildThatStopsReadingEndsNormally) {
  // No SIGPIPE reaches this process when the child leaves its input unread.
  const ChildResult r = shell("exit 0", std::string(8 << 20, 'x'));
  EXPECT_EQ(r.end, End::Exited);
  EXPECT_EQ(r.code, 0);
}

TEST(ChildProcess, ACrashIsReportedWithItsSignal) {
  const ChildResult r = shell("kill -SEGV $$");
  EXPECT_EQ(r.end, End::Signalled);
  EXPECT_EQ(r.code, SIGSEGV);
}

TEST(ChildProcess, AHangIsKilledAtTheTimeLimitWithWhatItStarted) {
  const auto started = std::chrono::steady_clock::now();
  // The background sleep keeps the output open: only killing the whole
  // group ends the wait.
  const ChildResult r = shell("sleep 30 & sleep 30", {}, 300ms);
  EXPECT_EQ(r.end, End::TimedOut);
  EXPECT_LT(std::chrono::steady_clock::now() - started, 5s);
}

TEST(ChildProcess, TooMuchOutputIsCutOff) {
  const ChildResult r = shell("while :; do echo flood; done", {}, 10s, 1000);
  EXPECT_EQ(r.end, End::OutputTooLarge);
  EXPECT_TRUE(r.output.empty());
  // Exactly the cap is still an answer.
  const ChildResult exact = shell("printf 12345", {}, 10s, 5);
  EXPECT_EQ(exact.end, End::Exited);
  EXPECT_EQ(exact.output, "12345");
}

TEST(ChildProcess, AProgramThatIsNotThereDoesNotStart) {
  ChildRun run;
  run.program = "/nonexistent/helper";
  const ChildResult r = run_child(run);
  EXPECT_EQ(r.end, End::NotStarted);
  EXPECT_NE(r.code, 0);
}

TEST(ChildProcess, TheDracoHelperStopsAtItsMemoryLimit) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the helper sets no address-space limit under AddressSanitizer";
#endif
  // Reading 200 MB of input needs more than the 64 MB allowed.
  const std::string input(200 << 20, '\0');
  ChildRun run;
  run.program = TOOND_DRACO_DECODER_PATH;
  run.arguments = {"--memory-mb", "64", "--cpu-seconds", "10"};
  run.input = input;
  const ChildResult r = run_child(run);
  EXPECT_EQ(r.end, End::Exited);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.errors.find("memory limit of 64 MB"), std::string::npos) << r.errors;
}

TEST(ChildProcess, TheDracoHelperRefusesGarbageAndBadUsage) {
  ChildRun run;
  run.program = TOOND_DRACO_DECODER_PATH;
  run.arguments = {"--memory-mb", "256", "--cpu-seconds", "10", "--attribute", "0"};
  run.input = "certainly not Draco";
  ChildResult r = run_child(run);
  EXPECT_EQ(r.end, End::Exited);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.errors.find("not a Draco mesh"), std::string::npos) << r.errors;
  run.arguments = {"--memory-mb", "lots"};
  r = run_child(run);
  EXPECT_EQ(r.code, 2);
}

}  // namespace
}  // namespace toond::scene
