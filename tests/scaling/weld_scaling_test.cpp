// The weld's time at n and 2n positions (half of them a cluster of
// near-duplicates): linear, by a ratio. Timed, so it lives with the other
// scaling tests, which run one at a time and only in the plain build.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scene/mesh/position_weld.h"

namespace toond::scene {
namespace {

TEST(PositionWeld, TimeGrowsLinearly) {
  auto cloud = [](int n) {
    std::vector<glm::vec3> p;
    for (int i = 0; i < n; ++i) {
      p.emplace_back(std::sin(i * 0.7f), std::cos(i * 1.3f), std::sin(i * 0.11f));
      p.emplace_back(0.5f, 0.5f, 0.5f + (i % 3) * 1e-9f);
    }
    return p;
  };
  // The fastest of five: preemption by the other tests running beside this
  // one only ever adds time, so the least disturbed run measures the weld.
  auto fastest_ms = [&](int n) {
    std::vector<double> ms;
    for (int r = 0; r < 5; ++r) {
      std::vector<glm::vec3> p = cloud(n);
      const auto t0 = std::chrono::steady_clock::now();
      weld_positions(p);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return *std::min_element(ms.begin(), ms.end());
  };
  // The table is 16 bytes a slot, four slots a point: as n doubles it can
  // move from one cache level to the next (or past what the TLB maps), and
  // that step alone has measured 2.6 (1 to 2 MiB, on CI) and 3 (64 to 128
  // MiB, here) while the work per position stayed the same. So the ratio is
  // taken at sizes far apart, and the smallest must be linear: a cache step
  // shows at one size, while a quadratic weld would be 4 at every one. The
  // sizes start where the table is a few MiB: on 2026-11-28 this box
  // measured 2.2–2.3 from 50,000 to 100,000 points, 2.3–2.4 to 200,000,
  // 2.3–2.9 to 400,000, 3.4–4.5 to 800,000 and 2.7–3.3 to 1.6 million, and
  // CI failed once at 2.52 when 200,000 to 400,000 was the smallest pair.
  double best_ratio = 1e9;
  for (const int n : {25000, 50000, 100000, 200000, 400000}) {
    const double small = fastest_ms(n), large = fastest_ms(2 * n);
    std::printf("[weld] %d points %.2f ms, twice the points %.2f ms: %.2f\n", 2 * n, small, large, large / small);
    best_ratio = std::min(best_ratio, large / small);
  }
  EXPECT_LT(best_ratio, 2.5);
}

}  // namespace
}  // namespace toond::scene
