// Default framing fits what the model covers in the image, and the outline
// width is one number for every method.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "render/plan/camera.h"
#include "render/plan/outline_width.h"
#include "scene/mesh/extreme_points.h"
#include "scene/mesh/mesh_processing.h"

namespace toond::render {
namespace {

// Points of a unit sphere, denser than any tessellation the tests use.
std::vector<glm::vec3> sphere_points(int n) {
  std::vector<glm::vec3> points;
  const double golden = std::acos(-1.0) * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double y = 1.0 - (i + 0.5) * 2.0 / n;
    const double r = std::sqrt(1.0 - y * y);
    points.emplace_back(r * std::cos(golden * i), y, r * std::sin(golden * i));
  }
  return points;
}

// How far out, in NDC, the farthest of `points` projects (0..1 fills the
// limiting dimension).
double projected_extent(const CameraSetup& cam, const std::vector<glm::vec3>& points, double aspect) {
  double extent = 0;
  for (const glm::vec3& p : points) {
    const glm::dvec4 clip = cam.projection * cam.view * glm::dvec4(glm::dvec3(p), 1.0);
    const double x = clip.x / clip.w, y = clip.y / clip.w;
    extent = std::max(extent, aspect >= 1.0 ? std::abs(y) : std::abs(x));
  }
  return extent;
}

TEST(ExtremePoints, AreFewAndLieOnTheOutline) {
  const std::vector<glm::vec3> sphere = sphere_points(20000);
  const std::vector<glm::vec3> extremes = scene::extreme_points(sphere);
  EXPECT_LE(extremes.size(), static_cast<std::size_t>(scene::kExtremeDirections));
  EXPECT_GT(extremes.size(), 100u);
  for (const glm::vec3& p : extremes) EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
}

// What extreme_points must find, by the plain scan it stands for: along each
// of the same directions, the first of the points that reach farthest.
std::vector<glm::vec3> scanned_extremes(const std::vector<glm::vec3>& points) {
  const double golden = std::acos(-1.0) * (3.0 - std::sqrt(5.0));
  std::vector<std::size_t> first;
  for (int i = 0; i < scene::kExtremeDirections; ++i) {
    const double y = 1.0 - (i + 0.5) * 2.0 / scene::kExtremeDirections;
    const double r = std::sqrt(1.0 - y * y);
    const glm::dvec3 dir(r * std::cos(golden * i), y, r * std::sin(golden * i));
    double best = -std::numeric_limits<double>::infinity();
    std::size_t at = 0;
    for (std::size_t v = 0; v < points.size(); ++v) {
      const double reach = glm::dot(glm::dvec3(points[v]), dir);
      if (reach > best) {
        best = reach;
        at = v;
      }
    }
    first.push_back(at);
  }
  std::sort(first.begin(), first.end());
  first.erase(std::unique(first.begin(), first.end()), first.end());
  std::vector<glm::vec3> out;
  for (const std::size_t v : first) out.push_back(points[v]);
  return out;
}

// Blocks of points are skipped where they cannot reach farther than a point
// already found; ties, copies, a circle walked in order (every block the
// best for a while), a flat cloud far from the origin and points that are
// not numbers must still give exactly the scan's points.
TEST(ExtremePoints, AreTheFirstOfTheFarthestAsAScanFindsThem) {
  std::mt19937 random(45);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::vector<std::vector<glm::vec3>> sets;
  std::vector<glm::vec3> grid, circle, star, flat, with_nan = sphere_points(3000);
  for (int i = 0; i < 2000; ++i) grid.emplace_back(i % 5, (i / 5) % 5, (i / 25) % 5);
  for (int i = 0; i < 5000; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / 5000.0f;
    circle.emplace_back(std::cos(a), std::sin(a), 0.0f);
    const float r = i % 2 ? 0.6f : 1.0f;
    star.emplace_back(r * std::cos(a), r * std::sin(a), 0.0f);
  }
  for (int i = 0; i < 5000; ++i) star.push_back(star[static_cast<std::size_t>(i * 37 % 5000)]);  // copies after
  for (int i = 0; i < 4000; ++i) flat.emplace_back(1e6f + unit(random) * 1e3f, unit(random), unit(random) * 1e-6f);
  with_nan[17] = glm::vec3(std::nanf(""), 0.0f, 0.0f);
  with_nan[1000] = with_nan[2000] = glm::vec3(2.0f, 2.0f, 2.0f);
  for (const auto* set : {&grid, &circle, &star, &flat, &with_nan}) {
    const std::vector<glm::vec3> found = scene::extreme_points(*set), scanned = scanned_extremes(*set);
    ASSERT_EQ(found.size(), scanned.size());
    for (std::size_t i = 0; i < found.size(); ++i) {
      EXPECT_EQ(std::memcmp(&found[i], &scanned[i], sizeof(glm::vec3)), 0) << i << " of " << set->size() << " points";
    }
  }
  // The import's form searches only the first vertex at each point.
  EXPECT_EQ(scene::extreme_points(star, scene::group_by_position(star)), scanned_extremes(star));
}

// A sphere fills 85–92 % of the limiting dimension from any view, at any
// aspect, in either projection; the bounding sphere of its box left it at
// about half.
TEST(Framing, ASphereFillsMostOfTheLimitingDimension) {
  const std::vector<glm::vec3> sphere = sphere_points(20000);
  std::vector<glm::dvec3> outline;
  for (const glm::vec3& p : scene::extreme_points(sphere)) outline.emplace_back(p);
  const scene::Bounds bounds{glm::vec3(-1), glm::vec3(1)};
  for (const Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    for (const double aspect : {0.5, 1.0, 2.0}) {
      for (const double yaw : {0.0, 30.0, 123.0}) {
        CameraParams params;
        params.projection = projection;
        params.yaw_deg = yaw;
        params.pitch_deg = 15;
        const CameraSetup cam = fit_camera(params, bounds, aspect, outline);
        const double fill = projected_extent(cam, sphere, aspect);
        EXPECT_GE(fill, 0.85) << "aspect " << aspect << " yaw " << yaw;
        EXPECT_LE(fill, 0.92) << "aspect " << aspect << " yaw " << yaw;
      }
    }
  }
}

TEST(OutlineWidth, PixelsStayPixelsAndWorldUnitsConvertAtTheCentre) {
  const scene::Bounds bounds{glm::vec3(-1), glm::vec3(1)};
  CameraParams params;
  params.projection = Projection::Orthographic;
  const CameraSetup ortho = fit_camera(params, bounds, 1.0);
  OutlineParams outline;
  outline.width = 3;
  EXPECT_DOUBLE_EQ(outline_width_px(outline, ortho, true, 512), 3.0);
  outline.width = 200;
  EXPECT_DOUBLE_EQ(outline_width_px(outline, ortho, true, 512), kMaxOutlinePx);

  // One world unit is the image height over the view's height in units.
  outline.units = OutlineUnits::World;
  outline.width = 0.01f;
  const double half_height = 1.0 / ortho.projection[1][1];
  EXPECT_NEAR(outline_width_px(outline, ortho, true, 512), 0.01 * 256.0 / half_height, 1e-3);

  // In perspective, at the target's distance: farther is thinner.
  params.projection = Projection::Perspective;
  const CameraSetup near_cam = fit_camera(params, bounds, 1.0);
  params.distance = 2.0 * glm::length(near_cam.eye - near_cam.target);
  const CameraSetup far_cam = fit_camera(params, bounds, 1.0);
  EXPECT_NEAR(outline_width_px(outline, far_cam, false, 512), 0.5 * outline_width_px(outline, near_cam, false, 512),
              1e-6);
  outline.width = 1e6f;
  EXPECT_DOUBLE_EQ(outline_width_px(outline, near_cam, false, 512), kMaxOutlinePx);
}

}  // namespace
}  // namespace toond::render
