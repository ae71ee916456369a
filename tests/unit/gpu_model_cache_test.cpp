// The GPU model cache's limits, on a real context (llvmpipe on CI).
#include <gtest/gtest.h>

#include "render/frame/gpu_model_cache.h"
#include "scene/import/bundle_import.h"
#include "scene/import/demo_model.h"
#include "support/gl_context_test.h"

namespace toond::render {
namespace {

class GpuModelCacheTest : public test::GlContextTest {
 protected:
  static const scene::Model& demo() {
    static const scene::Model model = scene::import_bundle(scene::make_demo_bundle());
    return model;
  }
};

TEST_F(GpuModelCacheTest, EvictsLeastRecentlyUsedBeyondItsBytes) {
  const std::size_t one = GpuModel(demo()).gpu_bytes();
  ASSERT_GT(one, 0u);
  GpuModelCache cache(100, one * 2 + one / 2);  // room for two by bytes, many by count
  cache.get("a", demo());
  cache.get("b", demo());
  cache.get("a", demo());  // a is now the most recent
  cache.get("c", demo());
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.bytes(), 2 * one);
  // b went: asking for it uploads again and pushes out a (least recent now).
  cache.get("b", demo());
  cache.get("c", demo());
  cache.get("a", demo());
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_LE(cache.bytes(), one * 2 + one / 2);
}

TEST_F(GpuModelCacheTest, CountLimitAndPinnedScenes) {
  GpuModelCache by_count(2, std::size_t{1} << 40);
  for (const char* k : {"a", "b", "c"}) by_count.get(k, demo());
  EXPECT_EQ(by_count.size(), 2u);
  // A scene of three objects holds all three while it renders.
  GpuModelCache tight(1, std::size_t{1} << 40);
  const std::vector<std::string> scene = {"x", "y", "z"};
  for (const auto& k : scene) tight.get(k, demo(), scene);
  EXPECT_EQ(tight.size(), 3u);
  tight.get("w", demo());
  EXPECT_EQ(tight.size(), 1u) << "the next load trims back to the limit";
  tight.forget("w");
  EXPECT_EQ(tight.size(), 0u);
  EXPECT_EQ(tight.bytes(), 0u);
}

}  // namespace
}  // namespace toond::render
