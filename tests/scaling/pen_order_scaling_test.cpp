// A line drawing's pen order (render/vector/pen_order.h) at n and 2n
// strokes: linear, by a ratio. The strokes are those of a drawing of many
// separate parts (a grid of small closed squares over a 2048² image, each
// nudged off the grid), where the greedy walk leaves strays behind and
// must come back for them from far away.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "render/vector/pen_order.h"

namespace toond::render::vector {
namespace {

std::vector<Polyline> squares(int k) {
  std::vector<Polyline> out;
  const double pitch = 2048.0 / k, side = 0.6 * pitch;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      const glm::dvec2 at(i * pitch + 0.2 * pitch * std::sin(i * 1.7 + j * 0.3),
                          j * pitch + 0.2 * pitch * std::cos(j * 2.1 + i * 0.7));
      Polyline square;
      square.points = {at, at + glm::dvec2(side, 0), at + glm::dvec2(side, side), at + glm::dvec2(0, side)};
      square.closed = true;
      out.push_back(square);
    }
  }
  return out;
}

TEST(PenOrder, TimeGrowsLinearly) {
  // The fastest of five: other work on the box only ever adds time.
  const auto fastest_ms = [](int k) {
    std::vector<double> ms;
    for (int r = 0; r < 5; ++r) {
      std::vector<Polyline> paths = squares(k);
      const auto t0 = std::chrono::steady_clock::now();
      order_for_pen(paths);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      EXPECT_EQ(paths.size(), static_cast<std::size_t>(k) * k);
    }
    return *std::min_element(ms.begin(), ms.end());
  };
  // k and k·√2 squares a side: n and 2n strokes.
  double best_ratio = 1e9;
  for (const auto& [k, k2] : {std::pair{100, 141}, std::pair{141, 200}, std::pair{200, 283}}) {
    const double small = fastest_ms(k), large = fastest_ms(k2);
    std::printf("[pen order] %d strokes %.2f ms, %d strokes %.2f ms: %.2f\n", k * k, small, k2 * k2, large,
                large / small);
    best_ratio = std::min(best_ratio, large / small);
  }
  EXPECT_LT(best_ratio, 2.5);
}

}  // namespace
}  // namespace toond::render::vector
