// The hull's faces left out before drawing (render/cull/hull_cull.h): which
// edges pair up, which faces a view leaves out on the CPU, and, with a GL
// context, that leaving them out changes no byte of any image while it
// does leave most of them out.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <span>
#include <sstream>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/egl_context.h"
#include "gpu/gl.h"
#include "model_checks.h"
#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "render/cull/background_thread.h"
#include "render/cull/hull_cull.h"
#include "render/frame/gpu_model.h"
#include "render/run/renderer.h"
#include "scene/import/bundle_import.h"
#include "support/generated_models.h"
#include "support/gl_context_test.h"
#include "support/in_process_render.h"
#include "support/shared_models.h"

namespace toond::render {
namespace {

HullCullMesh::Stream stream(const std::vector<glm::vec3>& values) {
  return std::make_shared<const std::vector<glm::vec3>>(values);
}

HullCullMesh mesh_of(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
  const std::vector<scene::Submesh> one = {{0, static_cast<std::uint32_t>(indices.size()), 0}};
  return HullCullMesh(stream(positions), stream(std::vector<glm::vec3>(positions.size(), glm::vec3(0.0f))), indices,
                      one);
}

TEST(HullCull, OnlyAnEdgeWalkedOnceEachWayByTwoFacesHasANeighbour) {
  // Two triangles of a square, the second's copy of the diagonal's ends
  // made separate vertices at the same places (a texture seam).
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 1, 0}};
  const HullCullMesh square = mesh_of(positions, {0, 1, 2, 4, 5, 3});
  EXPECT_EQ(square.neighbour(0, 2), 1);  // 2 → 0 in the first, 0 → 2 in the second
  EXPECT_EQ(square.neighbour(1, 0), 0);
  EXPECT_EQ(square.neighbour(0, 0), -1);  // the square's rim
  // The second walked the same way round as the first: a fold, no pair.
  const HullCullMesh folded = mesh_of(positions, {0, 1, 2, 5, 4, 3});
  EXPECT_EQ(folded.neighbour(0, 2), -1);
  // Three faces on one edge: none of them pairs.
  const std::vector<glm::vec3> fin = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  const HullCullMesh three = mesh_of(fin, {0, 1, 2, 1, 0, 3, 1, 0, 4});
  for (std::size_t t = 0; t < 3; ++t) EXPECT_EQ(three.neighbour(t, 0), -1) << t;
}

// An orthographic view of the unit sphere down -z filling `size` pixels.
HullCullView sphere_view(int size, double width_px) {
  HullCullView view;
  view.clip = glm::scale(glm::dmat4(1.0), glm::dvec3(0.8, 0.8, 0.4));  // radius 0.8 of the half-size
  view.width_px = width_px;
  view.world_per_px_at_w1 = 2.0 / (0.8 * size);
  view.viewport_width = size;
  view.viewport_height = size;
  return view;
}

TEST(HullCull, ASphereKeepsOnlyTheFacesNearItsSilhouette) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(96, 48));
  const scene::Mesh& mesh = sphere.mesh;
  const HullCullMesh cull(stream(mesh.positions), stream(mesh.outline_normals), mesh.indices, mesh.submeshes);
  const int size = 256;
  const double width = 3.0;
  const std::optional<HullSubset> subset = hull_faces_that_may_show(cull, sphere_view(size, width));
  ASSERT_TRUE(subset);
  // Most faces, toward the camera or away from it, lie well inside the disk.
  const std::size_t triangles = mesh.indices.size() / 3;
  EXPECT_GT(subset->culled_triangles, triangles / 3);
  EXPECT_EQ(subset->indices.size() / 3 + subset->culled_triangles, triangles);
  // Every face left out lies further inside the silhouette than its hull
  // face can reach.
  const double radius_px = 0.4 * size;
  std::vector<bool> kept(triangles, false);
  std::map<std::array<std::uint32_t, 3>, int> kept_faces;
  for (std::size_t e = 0; e < subset->indices.size(); e += 3) {
    ++kept_faces[{subset->indices[e], subset->indices[e + 1], subset->indices[e + 2]}];
  }
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::array<std::uint32_t, 3> face = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
    if (kept_faces.contains(face)) continue;
    for (std::uint32_t v : face) {
      const glm::vec3& p = mesh.positions[v];
      const double from_middle_px = glm::length(glm::dvec2(p.x, p.y)) * radius_px;
      EXPECT_LT(from_middle_px, radius_px - width) << t;
    }
  }
}

// Twice the signed area of a face's outline in the xy plane: the sphere's
// offsets are its normals, so its hull face turns the same way.
double xy_area2(const scene::Mesh& mesh, std::span<const std::uint32_t> face) {
  const glm::dvec2 a(mesh.positions[face[0]]), b(mesh.positions[face[1]]), c(mesh.positions[face[2]]);
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

TEST(HullCull, FacesSureToTurnToTheCulledSideAreSetApartAfterTheRest) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(96, 48));
  const scene::Mesh& mesh = sphere.mesh;
  const HullCullMesh cull(stream(mesh.positions), stream(mesh.outline_normals), mesh.indices, mesh.submeshes);
  HullCullView view = sphere_view(256, 3.0);
  // Where the hull pass draws both sides, nothing is set apart.
  const std::optional<HullSubset> both = hull_faces_that_may_show(cull, view);
  ASSERT_TRUE(both);
  EXPECT_EQ(both->turned_away_triangles(), 0u);
  EXPECT_TRUE(both->turned_away.empty());
  EXPECT_EQ(both->facing_index_count(), both->indices.size());
  view.hull_hidden = HiddenFaces::Back;
  const std::optional<HullSubset> subset = hull_faces_that_may_show(cull, view);
  ASSERT_TRUE(subset);
  // The same faces are kept; those turned away from the camera (the view
  // looks down -z) near the silhouette go after the rest.
  EXPECT_EQ(subset->culled_triangles, both->culled_triangles);
  EXPECT_EQ(subset->indices.size(), both->indices.size());
  EXPECT_GT(subset->turned_away_triangles(), 0u);
  ASSERT_EQ(subset->turned_away.size(), subset->submeshes.size());
  const std::size_t facing = subset->facing_index_count();
  // The ranges set apart follow the rest one after another, a submesh's
  // material each, to the end.
  std::size_t next = facing;
  for (std::size_t k = 0; k < subset->turned_away.size(); ++k) {
    EXPECT_EQ(subset->turned_away[k].first_index, next) << k;
    EXPECT_EQ(subset->turned_away[k].material, subset->submeshes[k].material) << k;
    next += subset->turned_away[k].index_count;
  }
  EXPECT_EQ(next, subset->indices.size());
  for (std::size_t e = facing; e < subset->indices.size(); e += 3) {
    EXPECT_LT(xy_area2(mesh, std::span(subset->indices).subspan(e, 3)), 0.0) << e;
  }
  // Faces edge-on to the camera, whose hull faces may turn either way, stay
  // with the rest: some of the kept faces turning away are not set apart.
  std::size_t away_among_facing = 0;
  for (std::size_t e = 0; e < facing; e += 3) {
    away_among_facing += xy_area2(mesh, std::span(subset->indices).subspan(e, 3)) < 0.0 ? 1 : 0;
  }
  EXPECT_GT(away_among_facing, 0u);
  // A mirrored object's hull pass culls the other side.
  view.hull_hidden = HiddenFaces::Front;
  const std::optional<HullSubset> mirrored = hull_faces_that_may_show(cull, view);
  ASSERT_TRUE(mirrored);
  for (std::size_t e = mirrored->facing_index_count(); e < mirrored->indices.size(); e += 3) {
    EXPECT_GT(xy_area2(mesh, std::span(mirrored->indices).subspan(e, 3)), 0.0) << e;
  }
}

// Two OBJ files' meshes as one: the second's face indices moved past the
// first's vertices (both written as sphere_obj writes, one normal a vertex).
std::string merged_obj(const std::string& first, const std::string& second) {
  std::size_t vertices = 0;
  for (std::size_t at = first.find("\nv "); at != std::string::npos; at = first.find("\nv ", at + 1)) ++vertices;
  std::string out = first;
  std::istringstream lines(second);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("f ", 0) != 0) {
      out += line + "\n";
      continue;
    }
    std::string moved = "f";
    std::istringstream corners(line.substr(2));
    for (std::string corner; corners >> corner;) {
      const std::size_t slash = corner.find("//");
      const std::size_t v = std::stoul(corner.substr(0, slash)) + vertices;
      moved += " " + std::to_string(v) + "//" + std::to_string(v);
    }
    out += moved + "\n";
  }
  return out;
}

// A small sphere in front of a large one, as one mesh: inside the large
// one's disk the small one's rim ends its own cover, but the large one lies
// under both sides of it, so the hull's faces along that rim, which the
// edge test alone keeps, are left out.
std::string sphere_before_sphere_obj() {
  return merged_obj(test::sphere_obj(96, 48), test::sphere_obj(24, 12, 0.35, glm::dvec3(0.2, 0.1, 1.3)));
}

TEST(HullCull, ARimWithTheModelUnderBothSidesLeavesItsFacesOut) {
  const scene::Model alone =
      scene::test_checks::model_of_obj(test::sphere_obj(24, 12, 0.35, glm::dvec3(0.2, 0.1, 1.3)));
  const scene::Model both = scene::test_checks::model_of_obj(sphere_before_sphere_obj());
  HullCullView view = sphere_view(256, 2.0);
  // How many of the small sphere's faces (its vertices come last) are kept.
  const auto small_kept = [&view](const scene::Mesh& mesh, std::uint32_t first_small_vertex) {
    const HullCullMesh cull(stream(mesh.positions), stream(mesh.outline_normals), mesh.indices, mesh.submeshes);
    const std::optional<HullSubset> subset = hull_faces_that_may_show(cull, view);
    EXPECT_TRUE(subset);
    std::size_t kept = 0;
    for (std::size_t e = 0; subset && e < subset->indices.size(); e += 3)
      kept += subset->indices[e] >= first_small_vertex;
    return kept;
  };
  const std::size_t alone_kept = small_kept(alone.mesh, 0);
  const auto first_small = static_cast<std::uint32_t>(both.mesh.positions.size() - alone.mesh.positions.size());
  EXPECT_GT(alone_kept, 400u) << "its own silhouette's faces";
  EXPECT_LT(small_kept(both.mesh, first_small) * 2, alone_kept);
  // Without the layers (as at one sample a pixel) the edge test keeps them.
  view.count_layers = false;
  EXPECT_GE(small_kept(both.mesh, first_small) * 2, alone_kept);
}

TEST(HullCull, AVertexOutsideTheDepthRangeTurnsTheCullOff) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(24, 12));
  const HullCullMesh cull(stream(sphere.mesh.positions), stream(sphere.mesh.outline_normals), sphere.mesh.indices,
                          sphere.mesh.submeshes);
  HullCullView view = sphere_view(128, 2.0);
  EXPECT_TRUE(hull_faces_that_may_show(cull, view));
  view.clip = glm::scale(glm::dmat4(1.0), glm::dvec3(0.8, 0.8, 1.5));  // the sphere reaches past both planes
  EXPECT_FALSE(hull_faces_that_may_show(cull, view));
}

class HullCullRender : public test::GlContextTest {
 protected:
  static RenderParams params(const nlohmann::json& request) {
    return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(request));
  }
  struct Pair {
    RenderOutput culled;
    RenderOutput whole;
  };
  static Pair render_both_ways(const std::vector<std::pair<const scene::Model*, glm::dmat4>>& scene,
                               const RenderParams& p) {
    test::InProcessScene drawn(scene);
    Pair out;
    drawn.renderer().set_hull_cull(true);
    // The first frame has the cull meshes built, and draws the whole hull.
    const RenderOutput first = drawn.render(p);
    EXPECT_EQ(first.hull_faces_culled, 0u);
    drawn.renderer().settle();
    out.culled = drawn.render(p);
    drawn.renderer().set_hull_cull(false);
    out.whole = drawn.render(p);
    return out;
  }
  // The same bytes both ways; returns the culled render's output.
  static RenderOutput same_image(const std::vector<std::pair<const scene::Model*, glm::dmat4>>& scene,
                                 const nlohmann::json& request, const std::string& what) {
    Pair pair = render_both_ways(scene, params(request));
    EXPECT_EQ(pair.whole.hull_faces_culled, 0u);
    EXPECT_EQ(pair.whole.hull_faces_turned_away, 0u);
    EXPECT_TRUE(pair.culled.image.rgba == pair.whole.image.rgba) << what << " " << request;
    return std::move(pair.culled);
  }
  // The same bytes both ways; returns how many faces were left out.
  static std::size_t expect_same_image(const std::vector<std::pair<const scene::Model*, glm::dmat4>>& scene,
                                       const nlohmann::json& request, const std::string& what) {
    return same_image(scene, request, what).hull_faces_culled;
  }
};

const std::vector<nlohmann::json>& requests() {
  static const std::vector<nlohmann::json> all = {
      {{"width", 160}, {"height", 160}},
      {{"width", 160}, {"height", 160}, {"msaa", 1}, {"camera", {{"yaw", 30}, {"pitch", 20}}}},
      {{"width", 160}, {"height", 160}, {"outline", {{"width", 8}}}, {"camera", {{"yaw", -50}, {"pitch", -15}}}},
      {{"width", 160}, {"height", 160}, {"outline", {{"width", 0.05}, {"units", "world"}}}},
      {{"width", 160}, {"height", 160}, {"camera", {{"projection", "orthographic"}, {"pitch", 35}}}},
      {{"width", 160}, {"height", 160}, {"outline", {{"color_mode", "material"}}}},
      {{"width", 160}, {"height", 160}, {"floor", {{"enabled", true}}}, {"shadows", {{"enabled", true}}}},
  };
  return all;
}

// The first frame asks for a level's cull mesh and draws the whole hull;
// the mesh is built on the background thread, which may still be at it
// when the model is dropped (evicted from the cache): the build owns what
// it reads, so nothing it touches is freed under it (ASan checks).
TEST_F(HullCullRender, AModelDroppedWhileItsCullMeshIsBuiltLeavesTheBuildSafe) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(256, 128));
  BackgroundThread builder;
  {
    auto model = std::make_unique<GpuModel>(sphere);
    EXPECT_EQ(model->hull_cull_mesh(0, builder), nullptr);
    EXPECT_EQ(model->hull_cull_mesh(0, builder), nullptr) << "built once, not queued again";
  }
  builder.drain();
  // Kept, it is there once built.
  GpuModel kept(sphere);
  EXPECT_EQ(kept.hull_cull_mesh(0, builder), nullptr);
  builder.drain();
  const std::shared_ptr<const HullCullMesh> mesh = kept.hull_cull_mesh(0, builder);
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->indices().size(), sphere.mesh.indices.size());
}

// Left to its default, as the daemon leaves it, a renderer culls the hull
// on a CPU rasterizer (the test context is llvmpipe) and not on a GPU.
TEST_F(HullCullRender, TheDefaultCullsOnACpuRasterizerOnly) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(64, 32));
  test::InProcessScene drawn({{&sphere, glm::dmat4(1.0)}});
  const RenderParams p = params({{"width", 160}, {"height", 160}});
  EXPECT_EQ(drawn.render(p).hull_faces_culled, 0u);
  drawn.renderer().settle();
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool cpu = gpu::software_rasterizer(name ? name : "");
  EXPECT_EQ(drawn.render(p).hull_faces_culled > 0, cpu) << name;
}

TEST_F(HullCullRender, LeavingFacesOutChangesNoByteOfGeneratedModels) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(64, 32));
  const scene::Model cube = scene::test_checks::model_of_obj(test::cube_obj());
  const scene::Model messy =
      scene::test_checks::model_of_obj(test::exporter_sphere_obj({.segments = 64, .rings = 32, .jitter = 1e-7}));
  const scene::Model faceted = scene::test_checks::model_of_obj(
      test::exporter_sphere_obj({.segments = 48, .rings = 24, .normals = test::ExporterSphere::Normals::PerFace}));
  const scene::Model bare = scene::test_checks::model_of_obj(
      test::exporter_sphere_obj({.segments = 48, .rings = 24, .normals = test::ExporterSphere::Normals::None}));
  // The cube's twelve faces all reach its silhouette: it keeps them all.
  expect_same_image({{&cube, glm::dmat4(1.0)}}, requests().front(), "cube");
  // A one-sided disk seen from behind: the main pass draws its faces turned
  // away (it has no inside to hide), none of them counted as covering, so
  // no face has a covered point in its box and none may be left out.
  const scene::Model disk = scene::test_checks::model_of_obj(test::disk_obj(96));
  for (const int yaw : {0, 180}) {
    const std::size_t culled = expect_same_image({{&disk, glm::dmat4(1.0)}},
                                                 {{"width", 160}, {"height", 160}, {"camera", {{"yaw", yaw}}}}, "disk");
    if (yaw == 180) {
      EXPECT_EQ(culled, 0u);
    }
  }
  const scene::Model nested = scene::test_checks::model_of_obj(sphere_before_sphere_obj());
  for (const auto& [model, what] :
       {std::pair{&sphere, "sphere"}, std::pair{&messy, "messy"}, std::pair{&faceted, "per-face normals"},
        std::pair{&bare, "no normals"}, std::pair{&nested, "sphere before sphere"}}) {
    for (const nlohmann::json& request : requests()) {
      EXPECT_GT(expect_same_image({{model, glm::dmat4(1.0)}}, request, what), 0u) << what << " " << request;
    }
  }
}

// A long thin plank laid between two spheres: its hull corners lie over the
// spheres while its faces cross the background; a mirrored object (drawn
// with its other winding), one stretched unevenly and one grown evenly.
TEST_F(HullCullRender, LeavingFacesOutChangesNoByteOfScenes) {
  const scene::Model sphere = scene::test_checks::model_of_obj(test::sphere_obj(48, 24));
  const scene::Model cube = scene::test_checks::model_of_obj(test::cube_obj());
  const glm::dmat4 left = glm::translate(glm::dmat4(1.0), glm::dvec3(-2.0, 0.0, 0.0));
  const glm::dmat4 right = glm::translate(glm::dmat4(1.0), glm::dvec3(2.0, 0.0, 0.0));
  const glm::dmat4 plank =
      glm::rotate(glm::scale(glm::dmat4(1.0), glm::dvec3(2.2, 0.03, 0.03)), 0.05, glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 mirrored =
      glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.8, -0.5)), glm::dvec3(-1, 1, 1));
  const glm::dmat4 stretched =
      glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -1.8, 0.3)), glm::dvec3(1.6, 0.4, 1));
  // Grown alike on every axis: the cull turns its offsets by one factor.
  const glm::dmat4 grown =
      glm::rotate(glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -5.0)), glm::dvec3(2.5)), 0.4,
                  glm::dvec3(1.0, 1.0, 0.0));
  for (const nlohmann::json& request : requests()) {
    const std::size_t culled = expect_same_image(
        {{&sphere, left}, {&sphere, right}, {&cube, plank}, {&cube, mirrored}, {&sphere, stretched}, {&sphere, grown}},
        request, "scene");
    EXPECT_GT(culled, 0u) << request;
  }
}

TEST_F(HullCullRender, LeavingFacesOutChangesNoByteOfScannedModels) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::filesystem::path models = test::shared_models_dir();
  const scene::Model bunny = scene::import_bundle(scene::test_checks::bundle_from_folder(models / "stanford-bunny"));
  const scene::Model spot = scene::import_bundle(scene::test_checks::bundle_from_folder(models / "spot"));
  for (const auto& [model, what] : {std::pair{&bunny, "bunny"}, std::pair{&spot, "spot"}}) {
    for (const nlohmann::json& request : requests()) expect_same_image({{model, glm::dmat4(1.0)}}, request, what);
    // The default request at the benchmark's size leaves out most of them,
    // and sets apart some of the rest.
    const RenderOutput out = same_image({{model, glm::dmat4(1.0)}}, {{"width", 512}, {"height", 512}}, what);
    EXPECT_GT(out.hull_faces_culled, model->mesh.triangle_count() / 10) << what;
    EXPECT_GT(out.hull_faces_turned_away, 0u) << what;
  }
}

// Files a real exporter wrote (tests/exported/blender): a CAD-like part
// as STL without normals and as PLY, the character's rest pose the same
// two ways, and a textured cube as glTF (whose twelve faces all reach its
// silhouette: nothing to leave out).
TEST_F(HullCullRender, LeavingFacesOutChangesNoByteOfExportedFiles) {
  const std::filesystem::path blender = TOOND_EXPORTED_DIR "/blender";
  for (const char* name : {"part.stl", "part.ply", "walker_rest.stl", "walker_rest.ply", "textured.glb"}) {
    const scene::Model model =
        scene::import_bundle(scene::test_checks::make_bundle({{name, test::read_file(blender / name)}}));
    for (const nlohmann::json& request : requests()) expect_same_image({{&model, glm::dmat4(1.0)}}, request, name);
    const RenderOutput out = same_image({{&model, glm::dmat4(1.0)}}, {{"width", 512}, {"height", 512}}, name);
    if (std::string(name) != "textured.glb") {
      EXPECT_GT(out.hull_faces_culled, 0u) << name;
    }
  }
}

// Seen from above, a bowl's inside shows through its opening (its cap
// turns toward the camera): the hull pass draws its culled side after all,
// and that draw needs the faces set apart as turned to it, which draw the
// ring along the far rim.
TEST_F(HullCullRender, TheSideDrawnWhereACapShowsTakesTheFacesSetApart) {
  const scene::Model bowl = scene::test_checks::model_of_obj(test::bowl_obj(48, 12));
  // In one colour the hull is one draw; in the material's, one per material.
  for (const char* colour : {"fixed", "material"}) {
    for (const int pitch : {-30, 30, 50, 70}) {
      const nlohmann::json request = {
          {"width", 256}, {"height", 256}, {"camera", {{"pitch", pitch}}}, {"outline", {{"color_mode", colour}}}};
      const RenderOutput out = same_image({{&bowl, glm::dmat4(1.0)}}, request, "bowl");
      if (pitch >= 50) {
        EXPECT_GT(out.hull_faces_turned_away, 0u) << pitch;
      }
    }
  }
}
}  // namespace
}  // namespace toond::render
