#pragma once
// Times imports of heavy inputs the way the scaling test and the benchmark
// both need: the importing thread's CPU time (so other processes of a busy
// machine do not count), the median of a few runs, sizes n and 2n
// interleaved so a slow spell hits both alike.
#include <cstddef>

#include "support/heavy_inputs.h"

namespace toond::test {

struct ScalingMeasure {
  int n = 0;
  std::size_t bytes = 0;        // of the bundle at n
  double seconds_n = 0.0;       // median import_bundle CPU time at n
  double seconds_2n = 0.0;      // the same at 2n
  std::size_t triangles_n = 0;  // of the imported model at n
  std::size_t triangles_2n = 0;
  double ratio() const { return seconds_2n / seconds_n; }
};

// The calling thread's CPU time (user and system, page faults included):
// the import runs on it alone, and time the scheduler gives to other
// processes of a busy machine does not count.
double thread_seconds();

// Makes malloc reuse freed memory instead of returning it to the kernel and
// mapping fresh pages for the next import. On the 2-core VM a fresh page's
// first touch costs more the more pages a process maps at once: the same
// triangle 40,000 and 80,000 times took 36 and 159 ms (4.5×) with 44,000
// page faults, though callgrind counts exactly twice the instructions
// (2.01×); with memory reused, 33 and 67 ms (2.03×). The scaling test is
// about the importer's own work, so it measures with memory reused.
void keep_freed_memory_in_process();

// Imports `input` at n and 2n (import_bundle, as an upload does: levels of
// detail and enclosure included), `runs` times each, after one warm-up.
// Freed memory is kept in the process first (keep_freed_memory_in_process).
ScalingMeasure measure_scaling(const HeavyInput& input, int n, int runs);

}  // namespace toond::test
