// The weld's time at n and 2n positions (half of them a cluster of
// near-duplicates): linear, by a ratio. Timed, so it lives with the other
// scaling tests, which run one at a time and only in the plain build.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scene/position_weld.h"

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
  // The fastest of nine: preemption by the other tests running beside this
  // one only ever adds time, so the least disturbed run measures the weld.
  auto fastest_ms = [&](int n) {
    std::vector<double> ms;
    for (int r = 0; r < 9; ++r) {
      std::vector<glm::vec3> p = cloud(n);
      const auto t0 = std::chrono::steady_clock::now();
      weld_positions(p);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return *std::min_element(ms.begin(), ms.end());
  };
  // Sizes whose tables stay in the caches both: beyond them each access
  // costs more, which says nothing about the algorithm.
  const double small = fastest_ms(10000), large = fastest_ms(20000);
  std::printf("[weld] %.2f ms, twice the positions %.2f ms\n", small, large);
  EXPECT_LT(large / small, 2.5) << small << " ms against " << large << " ms";
}

}  // namespace
}  // namespace toond::scene
