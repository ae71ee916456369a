// toond_heavy_import_bench: each heavy construct of the scaling test
// (tests/support/heavy_inputs.cpp) imported at n and 2n, as a table of
// median milliseconds and the 2n/n ratio (linear: 2; the test's bound: 2.5).
//   toond_heavy_import_bench [--scale K (default 1: the test's sizes)] [--runs N (default 5)] [--only NAME]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/import_timing.h"

int main(int argc, char** argv) {
  double scale = 1.0;
  int runs = 5;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--scale") scale = std::atof(argv[i + 1]);
    else if (flag == "--runs") runs = std::atoi(argv[i + 1]);
    else if (flag == "--only") only = argv[i + 1];
  }
  std::printf("%-20s %9s %9s %12s %10s %10s %6s\n", "construct", "n", "MB at n", "triangles", "ms at n", "ms at 2n",
              "ratio");
  for (const auto& input : toond::test::heavy_inputs()) {
    if (!only.empty() && input.name != only) continue;
    const int n = static_cast<int>(input.base_n * scale);
    const auto m = toond::test::measure_scaling(input, n, runs);
    std::printf("%-20s %9d %9.2f %12zu %10.1f %10.1f %6.2f\n", input.name.c_str(), n, m.bytes / 1e6, m.triangles_n,
                m.seconds_n * 1e3, m.seconds_2n * 1e3, m.ratio());
    std::fflush(stdout);
  }
}
