// The import's wall-time limit (the daemon's --max-import-seconds): past its
// deadline an import of any format stops with ImportLimitError naming
// ImportLimit::Seconds; within it, nothing changes.
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <string>

#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "support/generated_models.h"

namespace toond::scene {
namespace {

using test_checks::make_bundle;

std::optional<ImportLimit> limit_named_by(const Bundle& bundle, const ImportLimits& limits) {
  try {
    import_bundle(bundle, limits);
  } catch (const ImportLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("nothing was stored"), std::string::npos) << e.what();
    return e.limit();
  }
  return std::nullopt;
}

TEST(ImportTimeLimit, AnImportPastItsDeadlineIsAbandonedNamingTheLimit) {
  ImportLimits limits;
  limits.max_seconds = 1e-9;
  EXPECT_EQ(limit_named_by(make_bundle({{"s.obj", test::sphere_obj(64, 32)}}), limits), ImportLimit::Seconds);
  EXPECT_EQ(
      limit_named_by(make_bundle({{"s.m", "Vertex 1 0 0 0\nVertex 2 1 0 0\nVertex 3 0 1 0\nFace 1 1 2 3\n"}}), limits),
      ImportLimit::Seconds);
}

TEST(ImportTimeLimit, ADeadlineAlreadySetIsKept) {
  // A caller that started the clock earlier (the upload route) keeps it.
  ImportLimits limits;
  limits.max_seconds = 3600;
  limits.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  EXPECT_EQ(limit_named_by(make_bundle({{"s.obj", test::sphere_obj(16, 8)}}), limits), ImportLimit::Seconds);
}

TEST(ImportTimeLimit, WithinItTheModelIsTheSame) {
  const Bundle bundle = make_bundle({{"s.obj", test::sphere_obj(64, 32)}});
  ImportLimits limits;
  limits.max_seconds = 3600;
  const Model timed = import_bundle(bundle, limits);
  const Model untimed = import_bundle(bundle);
  EXPECT_EQ(timed.mesh.indices, untimed.mesh.indices);
  EXPECT_EQ(timed.mesh.lods.size(), untimed.mesh.lods.size());
}

}  // namespace
}  // namespace toond::scene
