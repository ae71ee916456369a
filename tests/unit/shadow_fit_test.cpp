#include <gtest/gtest.h>

#include <cmath>

#include "render/plan/shadow_fit.h"

namespace toond::render {
namespace {

TEST(ShadowFit, EveryCornerOfTheBoundsLandsInsideTheMap) {
  const scene::Bounds b{{-2, 0, -1}, {3, 1.5f, 0.5f}};
  for (const glm::dvec3 dir : {glm::dvec3(0, -1, 0), glm::dvec3(0.3, -1, -0.2), glm::dvec3(1, 0, 0),
                               glm::dvec3(0, 0, -1), glm::dvec3(-0.5, 0.2, 0.7)}) {
    const ShadowFit fit = fit_shadow(dir, b, 1024);
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 corner(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
      const glm::dvec4 clip = fit.view_projection * glm::dvec4(corner, 1.0);
      EXPECT_LT(std::abs(clip.x / clip.w), 1.0);
      EXPECT_LT(std::abs(clip.y / clip.w), 1.0);
      EXPECT_LT(std::abs(clip.z / clip.w), 1.0);
    }
    EXPECT_GT(fit.texel_world, 0.0);
    EXPECT_LT(fit.texel_world, 6.0 / 1024 * 1.2) << "the map hugs the bounds";
  }
}

TEST(ShadowFit, NearerToTheLightIsSmallerDepth) {
  const scene::Bounds b{{-1, -1, -1}, {1, 1, 1}};
  const ShadowFit fit = fit_shadow({0, -1, 0}, b, 512);
  const double top = (fit.view_projection * glm::dvec4(0, 1, 0, 1)).z;
  const double bottom = (fit.view_projection * glm::dvec4(0, -1, 0, 1)).z;
  EXPECT_LT(top, bottom);
}

}  // namespace
}  // namespace toond::render
