#pragma once
// Splitting one job's work over the cores (an image's encoding, a pose's
// vertices). Starting a thread costs tens of microseconds, a noticeable
// share of a one-millisecond encode, so helper threads are started once per
// process and woken for each job.
#include <functional>

namespace toond::parallel {

// Runs task(0) ... task(count - 1) and returns once all have finished. The
// calling thread runs tasks itself; at most `threads - 1` helpers join it,
// taken from a pool of hardware_concurrency - 1 threads shared by the whole
// process, so a busy pool just leaves more of the tasks to the caller and
// the process never runs more encoding threads than the hardware has (plus
// the callers). The first exception a task throws is rethrown here once
// every task has finished.
void run_tasks(int count, int threads, const std::function<void(int)>& task);

// The hardware's thread count, at least 1.
int hardware_threads();

}  // namespace toond::parallel
