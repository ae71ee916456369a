// Runs of faces the main pass leaves out as surely turned away from the
// camera (render/cull/facing_runs.h): which runs a view leaves out, where it
// leaves none, and, with a GL context, that leaving them out changes no
// byte of any image.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "model_checks.h"
#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "render/cull/facing_runs.h"
#include "render/run/renderer.h"
#include "scene/import/bundle_import.h"
#include "support/generated_models.h"
#include "support/gl_context_test.h"
#include "support/in_process_render.h"
#include "support/shared_models.h"

namespace toond::render {
namespace {

MeshViewer perspective_from(const glm::dvec3& eye) {
  MeshViewer viewer;
  viewer.eye = eye;
  viewer.pixel = 1.0 / 500.0;  // about 500 px across at distance 1
  return viewer;
}

// The triangles the runs leave for `viewer`, over every submesh.
std::vector<IndexRange> kept(const FacingRuns& runs, const scene::Mesh& mesh, const MeshViewer& viewer) {
  std::vector<IndexRange> all, one;
  for (std::size_t k = 0; k < mesh.submeshes.size(); ++k) {
    runs.ranges_facing(k, viewer, one);
    all.insert(all.end(), one.begin(), one.end());
  }
  return all;
}

bool kept_holds(const std::vector<IndexRange>& ranges, std::uint32_t index) {
  for (const IndexRange& r : ranges) {
    if (index >= r.first_index && index < r.first_index + r.index_count) return true;
  }
  return false;
}

TEST(FacingRuns, ASphereSeenFromOutsideLeavesOutOnlyFacesTurnedAway) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(96, 48));
  const scene::Mesh& mesh = sphere.mesh;
  const FacingRuns runs(mesh.positions, mesh.indices, mesh.submeshes);
  const glm::dvec3 eye(0.3, 0.4, 4.0);
  const std::vector<IndexRange> ranges = kept(runs, mesh, perspective_from(eye));
  std::size_t left_out = 0;
  for (std::uint32_t e = 0; e < mesh.indices.size(); e += 3) {
    if (kept_holds(ranges, e)) continue;
    ++left_out;
    const glm::dvec3 a(mesh.positions[mesh.indices[e]]), b(mesh.positions[mesh.indices[e + 1]]),
        c(mesh.positions[mesh.indices[e + 2]]);
    const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
    EXPECT_LT(glm::dot(normal, glm::normalize(eye - a)), -FacingRuns::kMinimumTurn) << e;
  }
  // From four radii away the eye sees a little less than half the sphere;
  // most of the rest lies in runs wholly turned away.
  const std::size_t triangles = mesh.indices.size() / 3;
  EXPECT_GT(left_out, triangles / 4);
  // Runs are merged where they meet: fewer ranges than runs kept.
  EXPECT_LT(ranges.size(), runs.run_count() / 2);
}

TEST(FacingRuns, OrthographicViewsLeaveOutTheFarSide) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(64, 32));
  const scene::Mesh& mesh = sphere.mesh;
  const FacingRuns runs(mesh.positions, mesh.indices, mesh.submeshes);
  MeshViewer viewer;
  viewer.orthographic = true;
  viewer.forward = glm::dvec3(0.0, 0.0, -1.0);
  viewer.pixel = 2.0 / 500.0;
  const std::vector<IndexRange> ranges = kept(runs, mesh, viewer);
  std::size_t left_out = 0;
  for (std::uint32_t e = 0; e < mesh.indices.size(); e += 3) {
    if (kept_holds(ranges, e)) continue;
    ++left_out;
    for (std::uint32_t k = 0; k < 3; ++k) EXPECT_LT(mesh.positions[mesh.indices[e + k]].z, 0.05f) << e;
  }
  EXPECT_GT(left_out, mesh.indices.size() / 3 / 4);
}

// Pixels so large that snapping a corner could turn a face: all drawn.
TEST(FacingRuns, NothingIsLeftOutWherePixelsAreCoarse) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(64, 32));
  const scene::Mesh& mesh = sphere.mesh;
  const FacingRuns runs(mesh.positions, mesh.indices, mesh.submeshes);
  MeshViewer coarse = perspective_from(glm::dvec3(0.0, 0.0, 4.0));
  std::size_t kept_indices = 0;
  for (const IndexRange& r : kept(runs, mesh, coarse)) kept_indices += r.index_count;
  EXPECT_LT(kept_indices, mesh.indices.size());
  coarse.pixel = 0.5;
  kept_indices = 0;
  for (const IndexRange& r : kept(runs, mesh, coarse)) kept_indices += r.index_count;
  EXPECT_EQ(kept_indices, mesh.indices.size());
}

TEST(FacingRuns, ARunWithADegenerateFaceIsAlwaysDrawn) {
  // A strip of faces turned away from an eye on +z, then one face with no
  // area: the first run is left out, the run holding the degenerate one not.
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  const std::size_t n = FacingRuns::kRunTriangles;
  for (std::size_t i = 0; i < 2 * n; ++i) {
    const auto x = static_cast<float>(i);
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), {{x, 0, 0}, {x, 1, 0}, {x + 1, 0, 0}});  // clockwise seen from +z
    indices.insert(indices.end(), {base, base + 1, base + 2});
  }
  positions[indices[3 * n + 1]] = positions[indices[3 * n]];  // the second run's first face: no area
  const std::vector<scene::Submesh> one = {{0, static_cast<std::uint32_t>(indices.size()), 0}};
  const FacingRuns runs(positions, indices, one);
  ASSERT_EQ(runs.run_count(), 2u);
  std::vector<IndexRange> ranges;
  runs.ranges_facing(0, perspective_from(glm::dvec3(n, 0.5, 50.0)), ranges);
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_EQ(ranges[0].first_index, 3 * n);
  EXPECT_EQ(ranges[0].index_count, 3 * n);
}

TEST(FacingRuns, OnlyASimilarityCarriesTheTestOver) {
  Viewer frame_viewer;
  frame_viewer.eye = glm::dvec3(1.0, 2.0, 10.0);
  const glm::dmat4 moved = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -2.0));
  const std::optional<MeshViewer> plain =
      viewer_in_mesh(moved * glm::scale(glm::dmat4(1.0), glm::dvec3(2.0)), frame_viewer, 0.01);
  ASSERT_TRUE(plain);
  EXPECT_NEAR(plain->eye.z, 6.0, 1e-12);  // (10 + 2) / 2
  EXPECT_NEAR(plain->pixel, 0.01, 1e-15);
  frame_viewer.orthographic = true;
  frame_viewer.forward = glm::dvec3(1.0, 0.0, 0.0);
  const std::optional<MeshViewer> mirrored =
      viewer_in_mesh(glm::scale(glm::dmat4(1.0), glm::dvec3(-2.0, 2.0, 2.0)), frame_viewer, 0.01);
  ASSERT_TRUE(mirrored);
  EXPECT_NEAR(mirrored->forward.x, -1.0, 1e-12);  // unit, and mirrored
  EXPECT_NEAR(mirrored->pixel, 0.005, 1e-15);     // orthographic: a pixel in mesh units
  EXPECT_FALSE(viewer_in_mesh(glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 1.0)), frame_viewer, 0.01));
}

class FacingRunsRender : public test::GlContextTest {
 protected:
  static RenderParams params(const nlohmann::json& request) {
    return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(request));
  }
  // The same bytes with runs left out and without; returns how many
  // triangles were left out.
  static std::size_t expect_same_image(const std::vector<std::pair<const scene::Model*, glm::dmat4>>& scene,
                                       const nlohmann::json& request, const std::string& what) {
    test::InProcessScene drawn(scene);
    const RenderParams p = params(request);
    const RenderOutput skipping = drawn.render(p);
    drawn.renderer().set_skip_turned_away_runs(false);
    const RenderOutput whole = drawn.render(p);
    EXPECT_EQ(whole.main_triangles_skipped, 0u);
    EXPECT_TRUE(skipping.image.rgba == whole.image.rgba) << what << " " << request;
    return skipping.main_triangles_skipped;
  }
};

const std::vector<nlohmann::json>& run_requests() {
  static const std::vector<nlohmann::json> all = {
      {{"width", 160}, {"height", 160}},
      {{"width", 160}, {"height", 160}, {"msaa", 1}, {"camera", {{"yaw", 30}, {"pitch", 20}}}},
      {{"width", 160}, {"height", 160}, {"camera", {{"yaw", -50}, {"pitch", -15}, {"zoom", 3}}}},
      {{"width", 160}, {"height", 160}, {"camera", {{"projection", "orthographic"}, {"pitch", 35}}}},
      {{"width", 160}, {"height", 160}, {"floor", {{"enabled", true}}}, {"shadows", {{"enabled", true}}}},
      {{"width", 160}, {"height", 160}, {"outline", {{"method", "edges"}}}, {"contour", {{"enabled", true}}}},
  };
  return all;
}

TEST_F(FacingRunsRender, LeavingRunsOutChangesNoByteOfGeneratedModels) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(64, 32));
  const scene::Model messy =
      scene::test_checks::model_of_obj(test::exporter_sphere_obj({.segments = 64, .rings = 32, .jitter = 1e-7}));
  const scene::Model faceted = scene::test_checks::model_of_obj(
      test::exporter_sphere_obj({.segments = 48, .rings = 24, .normals = test::ExporterSphere::Normals::PerFace}));
  const scene::Model bare = scene::test_checks::model_of_obj(
      test::exporter_sphere_obj({.segments = 48, .rings = 24, .normals = test::ExporterSphere::Normals::None}));
  for (const auto& [model, what] : {std::pair{&sphere, "sphere"}, std::pair{&messy, "messy"},
                                    std::pair{&faceted, "per-face normals"}, std::pair{&bare, "no normals"}}) {
    for (const nlohmann::json& request : run_requests()) {
      const std::size_t skipped = expect_same_image({{model, glm::dmat4(1.0)}}, request, what);
      // Zoomed in, the sphere reaches past the near plane: nothing is culled.
      const bool cut = request.contains("camera") && request["camera"].contains("zoom");
      EXPECT_EQ(skipped > 0, !cut) << what << " " << request;
    }
  }
  // Seen from above, the bowl's inside shows through its opening: the side
  // culled is drawn after all, whole.
  const scene::Model bowl = scene::test_checks::model_of_obj(test::bowl_obj(48, 12));
  for (const int pitch : {-30, 50}) {
    expect_same_image({{&bowl, glm::dmat4(1.0)}}, {{"width", 160}, {"height", 160}, {"camera", {{"pitch", pitch}}}},
                      "bowl");
  }
}

// A mirrored object (its culled side the other one) leaves runs out; one
// stretched unevenly, where the test does not carry over, leaves none.
TEST_F(FacingRunsRender, LeavingRunsOutChangesNoByteOfScenes) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(48, 24));
  const glm::dmat4 left = glm::translate(glm::dmat4(1.0), glm::dvec3(-2.0, 0.0, 0.0));
  const glm::dmat4 mirrored =
      glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(2.0, 0.0, 0.0)), glm::dvec3(-1, 1, 1));
  const glm::dmat4 stretched =
      glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -1.8, 0.3)), glm::dvec3(1.6, 0.4, 1));
  for (const nlohmann::json& request : run_requests()) {
    const std::size_t with_mirror = expect_same_image({{&sphere, left}, {&sphere, mirrored}}, request, "mirrored");
    const std::size_t one = expect_same_image({{&sphere, left}}, request, "one");
    EXPECT_GT(with_mirror, one) << request;
    EXPECT_EQ(expect_same_image({{&sphere, stretched}}, request, "stretched"), 0u) << request;
  }
}

TEST_F(FacingRunsRender, LeavingRunsOutChangesNoByteOfScannedModels) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::filesystem::path models = test::shared_models_dir();
  const scene::Model bunny = scene::import_bundle(scene::test_checks::bundle_from_folder(models / "stanford-bunny"));
  const scene::Model spot = scene::import_bundle(scene::test_checks::bundle_from_folder(models / "spot"));
  for (const auto& [model, what] : {std::pair{&bunny, "bunny"}, std::pair{&spot, "spot"}}) {
    for (const nlohmann::json& request : run_requests()) expect_same_image({{model, glm::dmat4(1.0)}}, request, what);
    const std::size_t skipped = expect_same_image({{model, glm::dmat4(1.0)}}, {{"width", 512}, {"height", 512}}, what);
    EXPECT_GT(skipped, model->mesh.triangle_count() / 10) << what;
  }
}

}  // namespace
}  // namespace toond::render
