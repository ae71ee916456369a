// Import warnings are grouped and capped: no answer carries more than a few
// kilobytes of them, whatever the input repeats.
#include <gtest/gtest.h>

#include <numeric>
#include <string>

#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "scene/reading/mesh_builder.h"

namespace toond::scene {
namespace {

std::size_t total_bytes(const std::vector<std::string>& warnings) {
  return std::accumulate(warnings.begin(), warnings.end(), std::size_t{0},
                         [](std::size_t n, const std::string& w) { return n + w.size(); });
}

TEST(ImportWarnings, RepeatsAreCountedOnceAndDistinctOnesCapped) {
  ImportWarnings warnings;
  for (int i = 0; i < 100000; ++i) warnings.add("m.obj: material 'm17' is not defined");
  warnings.add("m.obj: a one-off");
  for (int i = 0; i < 5000; ++i) warnings.add("m.obj: distinct " + std::to_string(i) + std::string(1000, 'x'));
  const std::vector<std::string> out = warnings.take();
  ASSERT_EQ(out.size(), ImportWarnings::kMaxWarnings + 1);
  EXPECT_EQ(out[0], "100000 × m.obj: material 'm17' is not defined");
  EXPECT_EQ(out[1], "m.obj: a one-off");
  EXPECT_EQ(out.back(), std::to_string(5000 - (ImportWarnings::kMaxWarnings - 2)) + " further warnings left out");
  for (const std::string& w : out) EXPECT_LE(w.size(), ImportWarnings::kMaxMessageBytes + 16) << w.substr(0, 40);
  EXPECT_LE(total_bytes(out), 12000u);
  EXPECT_TRUE(warnings.take().empty()) << "take() leaves it empty";
}

TEST(ImportWarnings, SummariesAreKeptWhenTheListIsFull) {
  ImportWarnings warnings;
  for (int i = 0; i < 500; ++i) warnings.add("m.obj: material " + std::to_string(i) + " not found");
  warnings.add_summary("m.obj: 499 triangles repeated the corners of another and were dropped");
  const std::vector<std::string> out = warnings.take();
  ASSERT_EQ(out.size(), ImportWarnings::kMaxWarnings + 2);
  EXPECT_EQ(out[ImportWarnings::kMaxWarnings], "m.obj: 499 triangles repeated the corners of another and were dropped");
  EXPECT_EQ(out.back(), std::to_string(500 - ImportWarnings::kMaxWarnings) + " further warnings left out");
  EXPECT_TRUE(warnings.take().empty());
}

// The upload answer of an OBJ that switches to an undefined material
// thousands of times (each time onto the same triangle: more would be slow
// until imports of many faces on one edge are linear, issue 15).
TEST(ImportWarnings, AnObjWithManyMaterialSwitchesAnswersAFewKilobytes) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 3000; ++i) obj += "usemtl m" + std::to_string(i % 7) + "\nf 1 2 3\n";
  const Model model = import_bundle(test_checks::make_bundle({{"m.obj", obj}}));
  EXPECT_LE(total_bytes(model.warnings), 4096u);
  ASSERT_FALSE(model.warnings.empty());
  // m0 is switched to 429 times (3000 over 7 names): one line, counted.
  EXPECT_EQ(model.warnings[0].rfind("429 × m.obj: ", 0), 0u) << model.warnings[0];
}

}  // namespace
}  // namespace toond::scene
