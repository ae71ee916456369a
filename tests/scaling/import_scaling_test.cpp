// Import time grows linearly with every construct a file can repeat or make
// large (tests/support/heavy_inputs.cpp): the same construct at n and 2n
// must take at most 2.5 times as long. A ratio holds on a noisy machine
// where an absolute time would not; the sizes are large enough that each
// import takes tens of milliseconds.
#include <gtest/gtest.h>

#include <ostream>

#include "support/import_timing.h"

namespace toond::test {
namespace {

constexpr double kLinearBound = 2.5;
constexpr int kRuns = 7;

}  // namespace

// gtest prints a parameter it cannot format as raw bytes.
void PrintTo(const HeavyInput& input, std::ostream* out) { *out << input.name; }

namespace {

class ImportScaling : public testing::TestWithParam<HeavyInput> {};

TEST_P(ImportScaling, TimeAtTwiceTheSizeIsAtMostTwoAndAHalfTimes) {
  const HeavyInput& input = GetParam();
  const ScalingMeasure m = measure_scaling(input, input.base_n, kRuns);
  RecordProperty("seconds_n", std::to_string(m.seconds_n));
  RecordProperty("seconds_2n", std::to_string(m.seconds_2n));
  EXPECT_LE(m.ratio(), kLinearBound) << input.what << ": n = " << m.n << " took " << m.seconds_n * 1e3
                                     << " ms, 2n took " << m.seconds_2n * 1e3 << " ms";
}

INSTANTIATE_TEST_SUITE_P(HeavyInputs, ImportScaling, testing::ValuesIn(heavy_inputs()),
                         [](const testing::TestParamInfo<HeavyInput>& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace toond::test
