// The benchmark's Pareto front (bench/pareto_plot.h): which sweep points
// count as beaten when times are medians of noisy repeats.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "pareto_plot.h"

namespace toond::bench {
namespace {

// A sweep point timed between `low` and `high` (its repeats' interquartile
// range) around `median`.
PlotPoint point(const char* label, double low, double median, double high, double error, std::size_t bytes = 1000) {
  PlotPoint p;
  p.label = label;
  p.time_low_ms = low;
  p.time_ms = median;
  p.time_high_ms = high;
  p.error = error;
  p.bytes = bytes;
  return p;
}

// The labels mark_pareto_front puts on the front.
std::set<std::string> front(std::vector<PlotPoint> points) {
  mark_pareto_front(points);
  std::set<std::string> labels;
  for (const PlotPoint& p : points) {
    if (p.on_front) labels.insert(p.label);
  }
  return labels;
}

using Labels = std::set<std::string>;

// "beaten": same time as "slow fine", worse error; "clearly slower": same
// error as "slow fine", measurably slower.
TEST(ParetoFront, MoreAccurateAndNotSlowerBeatsAPoint) {
  EXPECT_EQ(front({point("fast coarse", 4, 5, 6, 2.0), point("slow fine", 19, 20, 21, 0.5),
                   point("beaten", 19, 20, 21, 1.0), point("clearly slower", 29, 30, 31, 0.5)}),
            (Labels{"fast coarse", "slow fine"}));
}

// Two settings that draw the same image (same error) whose medians differ
// by less than their spread: neither beats the other.
TEST(ParetoFront, TheSameImageWithinTheNoiseKeepsBothOnTheFront) {
  EXPECT_EQ(front({point("msaa 4", 24, 26, 29, 1.0), point("msaa 2", 23, 25, 27, 1.0)}), (Labels{"msaa 4", "msaa 2"}));
}

// Without spread (one repeat) the front is the classic one: any faster
// point with the same error wins.
TEST(ParetoFront, WithoutSpreadTheFasterOfTwoEqualErrorsWins) {
  EXPECT_EQ(front({point("a", 10, 10, 10, 1.0), point("b", 10.5, 10.5, 10.5, 1.0)}), (Labels{"a"}));
}

// A lower error is enough to beat a point whose time overlaps.
TEST(ParetoFront, LowerErrorWithOverlappingTimeBeatsAPoint) {
  EXPECT_EQ(front({point("fine", 9, 11, 13, 0.4), point("coarse", 8, 10, 12, 0.8)}), (Labels{"fine"}));
}

// PNG level 0 encodes faster but answers with a 25 times larger file: it
// does not beat the compressed default; a smaller file at the same time
// and error does.
TEST(ParetoFront, SizeIsTheThirdAxis) {
  const PlotPoint png3 = point("png 3", 30, 31, 32, 1.0, 40000);
  const PlotPoint png0 = point("png 0", 27, 28, 29, 1.0, 1000000);
  EXPECT_EQ(front({png3, png0}), (Labels{"png 3", "png 0"}));
  EXPECT_EQ(front({png3, png0, point("png 9", 30, 31, 32, 1.0, 35000)}), (Labels{"png 0", "png 9"}));
}

}  // namespace
}  // namespace toond::bench
