#include "support/import_timing.h"

#include <malloc.h>
#include <algorithm>

#include <ctime>
#include <limits>
#include <vector>

#include "scene/import/bundle_import.h"

namespace toond::test {
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

namespace {

double seconds_to_import(const scene::Bundle& bundle, std::size_t* triangles = nullptr) {
  const double start = thread_seconds();
  const scene::Model model = scene::import_bundle(bundle);
  const double stop = thread_seconds();
  if (triangles) *triangles = model.mesh.triangle_count();
  return stop - start;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

void keep_freed_memory_in_process() {
  // Large blocks come from the heap, not fresh mappings, and freed memory
  // stays for the next import: 1 GiB and 4 GiB are past anything a
  // heavy input allocates.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
}

ScalingMeasure measure_scaling(const HeavyInput& input, int n, int runs) {
  keep_freed_memory_in_process();
  const scene::Bundle small = input.make(n);
  const scene::Bundle large = input.make(2 * n);
  ScalingMeasure m{n, small.total_bytes()};
  seconds_to_import(small, &m.triangles_n);
  seconds_to_import(large, &m.triangles_2n);
  std::vector<double> at_n, at_2n;
  for (int r = 0; r < runs; ++r) {
    at_n.push_back(seconds_to_import(small));
    at_2n.push_back(seconds_to_import(large));
  }
  m.seconds_n = median(at_n);
  m.seconds_2n = median(at_2n);
  return m;
}

}  // namespace toond::test
