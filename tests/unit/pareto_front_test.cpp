// The benchmark's Pareto front (bench/pareto_plot.h): which sweep points
// count as beaten when times are medians of noisy repeats.
#include <gtest/gtest.h>

#include "pareto_plot.h"

namespace toond::bench {
namespace {

PlotPoint point(const char* label, double low, double median, double high, double error,
                std::size_t bytes = 1000) {
  PlotPoint p;
  p.bytes = bytes;
  p.label = label;
  p.time_low_ms = low;
  p.time_ms = median;
  p.time_high_ms = high;
  p.error = error;
  return p;
}

bool on_front(const std::vector<PlotPoint>& points, const std::string& label) {
  for (const PlotPoint& p : points) {
    if (p.label == label) return p.on_front;
  }
  ADD_FAILURE() << "no point " << label;
  return false;
}

TEST(ParetoFront, MoreAccurateAndNotSlowerBeatsAPoint) {
  std::vector<PlotPoint> points = {point("fast coarse", 4, 5, 6, 2.0), point("slow fine", 19, 20, 21, 0.5),
                                   point("beaten", 19, 20, 21, 1.0), point("clearly slower", 29, 30, 31, 0.5)};
  mark_pareto_front(points);
  EXPECT_TRUE(on_front(points, "fast coarse"));
  EXPECT_TRUE(on_front(points, "slow fine"));
  EXPECT_FALSE(on_front(points, "beaten"));          // same time as "slow fine", worse error
  EXPECT_FALSE(on_front(points, "clearly slower"));  // same error as "slow fine", measurably slower
}

// Two settings that draw the same image (same error) whose medians differ
// by less than their spread: neither beats the other.
TEST(ParetoFront, TheSameImageWithinTheNoiseKeepsBothOnTheFront) {
  std::vector<PlotPoint> points = {point("msaa 4", 24, 26, 29, 1.0), point("msaa 2", 23, 25, 27, 1.0)};
  mark_pareto_front(points);
  EXPECT_TRUE(on_front(points, "msaa 4"));
  EXPECT_TRUE(on_front(points, "msaa 2"));
}

// Without spread (one repeat) the front is the classic one: any faster
// point with the same error wins.
TEST(ParetoFront, WithoutSpreadTheFasterOfTwoEqualErrorsWins) {
  std::vector<PlotPoint> points = {point("a", 10, 10, 10, 1.0), point("b", 10.5, 10.5, 10.5, 1.0)};
  mark_pareto_front(points);
  EXPECT_TRUE(on_front(points, "a"));
  EXPECT_FALSE(on_front(points, "b"));
}

// A lower error is enough to beat a point whose time overlaps.
TEST(ParetoFront, LowerErrorWithOverlappingTimeBeatsAPoint) {
  std::vector<PlotPoint> points = {point("fine", 9, 11, 13, 0.4), point("coarse", 8, 10, 12, 0.8)};
  mark_pareto_front(points);
  EXPECT_TRUE(on_front(points, "fine"));
  EXPECT_FALSE(on_front(points, "coarse"));
}

// PNG level 0 encodes faster but answers with a 25 times larger file: it
// does not beat the compressed default; a smaller file at the same time
// and error does.
TEST(ParetoFront, SizeIsTheThirdAxis) {
  std::vector<PlotPoint> points = {point("png 3", 30, 31, 32, 1.0, 40000), point("png 0", 27, 28, 29, 1.0, 1000000)};
  mark_pareto_front(points);
  EXPECT_TRUE(on_front(points, "png 3"));
  EXPECT_TRUE(on_front(points, "png 0"));
  points.push_back(point("png 9", 30, 31, 32, 1.0, 35000));
  mark_pareto_front(points);
  EXPECT_FALSE(on_front(points, "png 3"));
  EXPECT_TRUE(on_front(points, "png 9"));
}

}  // namespace
}  // namespace toond::bench
