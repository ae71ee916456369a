#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"

namespace toond::render {
namespace {

scene::Bounds box(glm::vec3 min, glm::vec3 max) { return {min, max}; }

glm::dvec3 project(const CameraSetup& cam, glm::dvec3 p) {
  const glm::dvec4 clip = cam.projection * cam.view * glm::dvec4(p, 1.0);
  return glm::dvec3(clip) / clip.w;
}

TEST(Camera, YawZeroPitchZeroLooksFromPlusZ) {
  CameraParams params;
  params.yaw_deg = 0;
  params.pitch_deg = 0;
  const auto cam = fit_camera(params, box({-1, -1, -1}, {1, 1, 1}), 1.0);
  EXPECT_NEAR(cam.eye.x, 0, 1e-9);
  EXPECT_NEAR(cam.eye.y, 0, 1e-9);
  EXPECT_GT(cam.eye.z, 1.0);
  // +X appears on the right, +Y at the top.
  EXPECT_GT(project(cam, {0.5, 0, 0}).x, 0);
  EXPECT_GT(project(cam, {0, 0.5, 0}).y, 0);
}

TEST(Camera, PositiveYawMovesTheEyeTowardPlusX) {
  CameraParams params;
  params.yaw_deg = 90;
  params.pitch_deg = 0;
  const auto cam = fit_camera(params, box({-1, -1, -1}, {1, 1, 1}), 1.0);
  EXPECT_GT(cam.eye.x, 1.0);
  EXPECT_NEAR(cam.eye.z, 0, 1e-9);
}

// Auto-framing: the bounding sphere fits inside the frame and fills most
// of it, for either projection and any aspect ratio.
TEST(Camera, FitKeepsTheBoundsInsideTheFrame) {
  for (Projection proj : {Projection::Perspective, Projection::Orthographic}) {
    for (double aspect : {0.5, 1.0, 2.0}) {
      CameraParams params;
      params.projection = proj;
      params.yaw_deg = 37;
      params.pitch_deg = 20;
      const auto cam = fit_camera(params, box({-2, -1, -0.5f}, {2, 1, 0.5f}), aspect);
      double extent = 0;
      for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? 2 : -2, i & 2 ? 1 : -1, i & 4 ? 0.5 : -0.5);
        const glm::dvec3 ndc = project(cam, corner);
        EXPECT_LE(std::abs(ndc.x), 1.0);
        EXPECT_LE(std::abs(ndc.y), 1.0);
        EXPECT_GT(ndc.z, -1.0) << "inside the near plane";
        EXPECT_LT(ndc.z, 1.0) << "inside the far plane";
        extent = std::max({extent, std::abs(ndc.x), std::abs(ndc.y)});
      }
      EXPECT_GT(extent, 0.5) << "the model fills a good part of the frame";
    }
  }
}

// The same shape at any scale projects to the same place.
TEST(Camera, FramingIsScaleInvariant) {
  CameraParams params;
  params.yaw_deg = 20;
  params.pitch_deg = 10;
  const glm::dvec3 probe(0.3, 0.2, 0.1);
  const auto unit = fit_camera(params, box({-1, -1, -1}, {1, 1, 1}), 1.0);
  const glm::dvec3 reference = project(unit, probe);
  for (float scale : {1e-4f, 1e4f}) {
    const auto cam = fit_camera(params, box(glm::vec3(-scale), glm::vec3(scale)), 1.0);
    const glm::dvec3 p = project(cam, probe * static_cast<double>(scale));
    EXPECT_NEAR(p.x, reference.x, 1e-6) << scale;
    EXPECT_NEAR(p.y, reference.y, 1e-6) << scale;
  }
}

TEST(Camera, DegenerateBoundsStillGiveAUsableCamera) {
  CameraParams params;
  const auto cam = fit_camera(params, box({0, 0, 0}, {0, 0, 0}), 1.0);
  EXPECT_GT(cam.near_plane, 0);
  EXPECT_GT(cam.far_plane, cam.near_plane);
  EXPECT_TRUE(std::isfinite(cam.eye.z));
}

TEST(Camera, CameraInsideTheBoundsKeepsAPositiveNearPlane) {
  CameraParams params;
  params.distance = 0.1;  // well inside a box of radius ~1.7
  const auto cam = fit_camera(params, box({-1, -1, -1}, {1, 1, 1}), 1.0);
  EXPECT_GT(cam.near_plane, 0);
  EXPECT_LT(cam.near_plane, 0.1);
}

}  // namespace
}  // namespace toond::render
