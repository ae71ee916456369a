// Import drops repeated triangles and measures what drawing a mesh costs;
// a request is priced from that before it is queued (issue: one heavy
// request cannot stall the service). No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "model_checks.h"
#include "render/plan/frame_plan.h"
#include "render/plan/pass_plan.h"
#include "render/plan/render_cost.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/crease_edges.h"
#include "scene/mesh/duplicate_triangles.h"
#include "scene/mesh/render_cost_profile.h"
#include "support/costly_models.h"

namespace toond {
namespace {

using scene::TriangleCorners;
using scene::test_checks::has_warning;
using scene::test_checks::make_bundle;
using scene::test_checks::warnings_of;

TriangleCorners tri(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) { return {{a, b, c}}; }

TEST(DuplicateTriangles, EveryRotationIsARepeatAndTheLastIsKept) {
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const std::vector<TriangleCorners> t = {tri(a, b, c), tri(b, c, a), tri(c, a, b), tri(a, b, c)};
  EXPECT_EQ(scene::last_of_each_triangle(t), (std::vector<bool>{false, false, false, true}));
}

TEST(DuplicateTriangles, TheOtherSideAndNearlyEqualCornersAreKept) {
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const glm::dvec3 c_near(0, std::nextafter(1.0, 2.0), 0);
  const std::vector<TriangleCorners> t = {tri(a, b, c), tri(a, c, b), tri(a, b, c_near)};
  EXPECT_EQ(scene::last_of_each_triangle(t), (std::vector<bool>{true, true, true}));
}

TEST(DuplicateTriangles, MinusZeroIsZero) {
  const std::vector<TriangleCorners> t = {tri({-0.0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
                                          tri({0.0, 0, 0}, {1, 0, 0}, {0, 1, -0.0})};
  EXPECT_EQ(scene::last_of_each_triangle(t), (std::vector<bool>{false, true}));
}

TEST(DuplicateTriangles, ImportKeepsOneOfARepeatedFaceAndSaysHowMany) {
  // Three materials over the same face, written with fresh vertices each
  // time: the one drawn last (the last material) is what showed before.
  const std::string obj =
      "mtllib t.mtl\n" + test::one_triangle_many_materials(3) + "usemtl other\nv 5 5 5\nv 6 5 5\nv 5 6 5\nf -3 -2 -1\n";
  const std::string mtl = "newmtl m0\nKd 1 0 0\nnewmtl m1\nKd 0 1 0\nnewmtl m2\nKd 0 0 1\nnewmtl other\nKd 1 1 1\n";
  const scene::Model m = scene::import_obj_bundle(make_bundle({{"t.obj", obj}, {"t.mtl", mtl}}));
  ASSERT_EQ(m.mesh.triangle_count(), 2u);
  EXPECT_TRUE(has_warning(m, "2 triangles repeated the corners of another and were dropped")) << warnings_of(m);
  std::vector<std::string> drawn;
  for (const scene::Submesh& s : m.mesh.submeshes)
    drawn.push_back(m.materials[static_cast<std::size_t>(s.material)].name);
  EXPECT_EQ(drawn, (std::vector<std::string>{"m2", "other"}));
}

// The file: no MTL, so each name is also a warning of its own; the
// count of repeats is not crowded out by them.
TEST(DuplicateTriangles, AHundredThousandRepeatsImportAsOne) {
  const scene::Model m = scene::import_obj_bundle(make_bundle({{"t.obj", test::one_triangle_many_materials(100000)}}));
  EXPECT_EQ(m.mesh.triangle_count(), 1u);
  EXPECT_TRUE(has_warning(m, "99999 triangles repeated")) << warnings_of(m);
}

scene::RenderCostProfile profile_of(const std::string& obj) {
  const scene::Model m = scene::import_obj_bundle(make_bundle({{"m.obj", obj}}));
  return m.mesh.cost;
}

const std::string kCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";

TEST(RenderCostProfile, ABoxIsTwoLayersFromEverySide) {
  // Each view meets the front face and the back one, nothing more.
  EXPECT_NEAR(profile_of(kCube).layers(), 2.0, 1e-6);
  for (const glm::dvec3 v : {glm::dvec3(1, 2, 3), glm::dvec3(0, 0, -1), glm::dvec3(-1, 0.1, 0)}) {
    EXPECT_NEAR(profile_of(kCube).layers_toward(v), 2.0, 1e-6) << v.x << " " << v.y << " " << v.z;
  }
}

TEST(RenderCostProfile, AStackOfFacesIsAsDeepAsItIsHigh) {
  // Each of the n triangles covers half the bounds' face.
  for (int n : {10, 1000}) {
    EXPECT_NEAR(profile_of(test::nearly_coincident_triangles(n)).layers(), n / 2.0, n * 1e-6) << n;
  }
}

TEST(RenderCostProfile, DoesNotDependOnPlaceOrScale) {
  std::string far_and_small;
  for (std::size_t start = 0; start < kCube.size();) {
    const std::size_t end = kCube.find('\n', start);
    const std::string line = kCube.substr(start, end - start);
    start = end + 1;
    if (line[0] != 'v') {
      far_and_small += line + "\n";
      continue;
    }
    double x, y, z;
    std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z);
    char buf[128];
    std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", 1e4 + x * 1e-3, -1e4 + y * 1e-3, z * 1e-3);
    far_and_small += buf;
  }
  const scene::RenderCostProfile a = profile_of(kCube);
  const scene::RenderCostProfile b = profile_of(far_and_small);
  EXPECT_NEAR(b.layers(), a.layers(), 1e-3);
  EXPECT_NEAR(b.edge_span(), a.edge_span(), 1e-3);
}

TEST(RenderCostProfile, SliversCrossTheFrameWithoutArea) {
  const scene::RenderCostProfile p = profile_of(test::crossing_slivers(1000));
  EXPECT_LT(p.layers(), 1.0);
  // Each sliver's longest edge is about one diagonal of the bounds, which
  // are twice as wide as one sliver's run.
  EXPECT_GT(p.edge_span(), 300.0);
}

// Pages of a book opened all the way round: from the spine's end each
// page is a line, from the side they stack thousands deep. A request is
// priced from its own view.
TEST(RenderCostProfile, LayersDependOnTheView) {
  std::string obj = "v 0 0 -1\nv 0 0 1\n";
  const int pages = 4000;
  for (int i = 0; i < pages; ++i) {
    const double a = 2 * 3.14159265358979 * i / pages;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  for (int i = 0; i < pages; ++i) obj += "f 1 2 " + std::to_string(i + 3) + "\n";
  const scene::RenderCostProfile p = profile_of(obj);
  EXPECT_LT(p.layers_toward({0, 0, 1}), 1.0);
  // From +X: Σ|sin a| × page area 1 over the box's 2 × 2 side: pages/(2π).
  EXPECT_NEAR(p.layers_toward({1, 0, 0}), pages / (2 * 3.14159265358979), pages * 0.01);
  EXPECT_NEAR(p.layers(), p.layers_toward({1, 0, 0}), pages * 0.01);
}

// The binned sums against the exact Σ|a·v| of every triangle: a sphere's
// normals spread over every bin, the worst case for binning.
TEST(RenderCostProfile, BinsAreCloseToTheExactSum) {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  const int rings = 40, segments = 80;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {
      const double th = 3.14159265358979 * r / rings, ph = 2 * 3.14159265358979 * s / segments;
      positions.emplace_back(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = static_cast<std::uint32_t>(r * (segments + 1) + s), b = a + 1,
                          c = a + static_cast<std::uint32_t>(segments + 1), d = c + 1;
      indices.insert(indices.end(), {a, c, b, b, c, d});
    }
  }
  const scene::RenderCostProfile p = scene::measure_render_cost(positions, indices, glm::vec3(2));
  for (const glm::dvec3 v : {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(1, 2, 3)), glm::dvec3(0, 1, 0)}) {
    double exact = 0;
    for (std::size_t t = 0; t < indices.size(); t += 3) {
      const glm::dvec3 a(positions[indices[t]]), b(positions[indices[t + 1]]), c(positions[indices[t + 2]]);
      exact += std::abs(glm::dot(glm::cross(b - a, c - a) * 0.5, v));
    }
    const double box = 4 * (std::abs(v.x) + std::abs(v.y) + std::abs(v.z));
    EXPECT_NEAR(p.layers_toward(v) / (exact / box), 1.0, 0.02) << v.x << " " << v.y << " " << v.z;
  }
}

render::RenderParams params_at(int width, int height, int msaa) {
  render::RenderParams p;
  p.width = width;
  p.height = height;
  p.msaa = msaa;
  return p;
}

render::RenderParams params_with_size(render::RenderParams p, int size) {
  p.width = size;
  p.height = size;
  return p;
}

render::RenderCost cost_of(const scene::Model& m, const render::RenderParams& p) {
  const scene::Mesh* meshes[] = {&m.mesh};
  const render::PassPlan passes = render::plan_passes(p, {});
  return render::predict_frame_cost({.params = p, .passes = passes, .line_px = p.outline.width}, meshes);
}

TEST(RenderCost, SamplesGrowWithPixelsSamplesAndLayers) {
  const scene::Model small = scene::import_obj_bundle(make_bundle({{"a.obj", test::nearly_coincident_triangles(100)}}));
  const scene::Model deep = scene::import_obj_bundle(make_bundle({{"b.obj", test::nearly_coincident_triangles(200)}}));
  const render::RenderCost base = cost_of(small, params_at(256, 256, 1));
  EXPECT_NEAR(cost_of(small, params_at(512, 512, 1)).samples / base.samples, 4.0, 1e-9);
  EXPECT_NEAR(cost_of(small, params_at(256, 256, 4)).samples / base.samples, 4.0, 1e-9);
  EXPECT_NEAR(cost_of(deep, params_at(256, 256, 1)).samples / base.samples, 2.0, 1e-3);
  EXPECT_NEAR(cost_of(deep, params_at(256, 256, 1)).triangles / base.triangles, 2.0, 1e-9);
}

TEST(RenderCost, OnlyPassesThatDrawTheMeshesCount) {
  const scene::Model m = scene::import_obj_bundle(make_bundle({{"a.obj", kCube}}));
  render::RenderParams p = params_at(256, 256, 1);
  p.outline.enabled = false;
  const double main_only = cost_of(m, p).samples;
  p.outline.enabled = true;  // the hull: a second pass over the meshes
  EXPECT_NEAR(cost_of(m, p).samples / main_only, 2.0, 1e-9);
  p.outline.edges = true;  // the edge prepass: a third
  EXPECT_NEAR(cost_of(m, p).samples / main_only, 3.0, 1e-9);
}

TEST(RenderCost, TheShadowPassCountsAtTheMapsSize) {
  const scene::Model m = scene::import_obj_bundle(make_bundle({{"a.obj", kCube}}));
  render::RenderParams p = params_at(256, 256, 1);
  p.outline.enabled = false;
  p.lights.push_back({});
  const double without = cost_of(m, p).samples;
  p.shadows.enabled = true;
  p.shadows.map_size = 1024;
  EXPECT_NEAR(cost_of(m, p).samples - without, 2.0 * 1024 * 1024, 1e-3);
}

// The edge pass reads every pixel's neighbours as far as a line of the
// width could reach: its price grows with the pixels and with the width,
// and silhouettes cost more than crease lines alone.
TEST(RenderCost, TheEdgePassCountsTheTexelsItsWalksRead) {
  const scene::Model m = scene::import_obj_bundle(make_bundle({{"a.obj", kCube}}));
  render::RenderParams p = params_at(256, 256, 1);
  EXPECT_EQ(cost_of(m, p).edge_texels, 0.0);  // the hull alone
  p.outline.edges = true;
  p.outline.width = 2;
  const render::RenderCost narrow = cost_of(m, p);
  EXPECT_NEAR(narrow.edge_texels, 256.0 * 256 * render::edge_texels_per_pixel(2, false), 1e-6);
  // A 2 px line reaches 3 pixels along an axis: four walks of 3.
  EXPECT_EQ(render::edge_texels_per_pixel(2, false), 4 * 3 + render::kSilhouettePixelTexels);
  EXPECT_EQ(render::edge_texels_per_pixel(2, true), 4 * 3 + render::kCreasePixelTexels);
  EXPECT_NEAR(cost_of(m, params_with_size(p, 512)).edge_texels / narrow.edge_texels, 4.0, 1e-9);
  // An 8 px line reaches 7: four more texels on each of the four walks.
  p.outline.width = 8;
  EXPECT_NEAR(cost_of(m, p).edge_texels - narrow.edge_texels, 256.0 * 256 * 4 * 4, 1e-6);
  EXPECT_NEAR(cost_of(m, p).units() - narrow.units(),
              (cost_of(m, p).edge_texels - narrow.edge_texels) * render::kEdgeTexelSamples / 1e6, 1e-9);
  EXPECT_NE(cost_of(m, p).describe().find("edge pass texels"), std::string::npos);
}

// Crease lines along the crease edges are priced by the edges (each set
// up alike) and the samples their lines cover, not by the frame's pixels:
// the cube's twelve edges, and its creased length (12 edges of 2 over a
// diagonal of 2√3) across the frame's side, the line's width wide. One
// sample a pixel, their coverage is gathered and laid over the frame: two
// more passes over it, whose pixels are weighted as render_cost.h's fit
// found them.
TEST(RenderCost, CreaseLinesArePricedByTheirEdgesNotThePixels) {
  scene::Model m = scene::import_obj_bundle(make_bundle({{"a.obj", kCube}}));
  scene::find_crease_edges(m.mesh);
  ASSERT_EQ(m.mesh.crease_edges.creased_at(40), 12u);
  render::ModelTraits hard;
  hard.hard_edged = true;
  hard.has_crease_edges = true;
  const scene::Mesh* meshes[] = {&m.mesh};
  const auto priced = [&](const render::RenderParams& p) {
    const render::PassPlan passes = render::plan_passes(p, hard);
    return render::predict_frame_cost({.params = p, .passes = passes, .line_px = p.outline.width}, meshes);
  };
  render::RenderParams p = params_at(256, 256, 4);
  p.outline.width = 2;
  render::RenderParams never = p;
  never.outline.creases = render::OutlineCreases::Never;
  const render::RenderCost creased = priced(p), bare = priced(never);
  EXPECT_EQ(creased.edge_texels, 0.0);
  EXPECT_EQ(creased.crease_edges, 12.0);
  const double line_samples = 12.0 * 2.0 / (2.0 * std::sqrt(3.0)) * 256 * 2 * 4;
  EXPECT_NEAR(creased.samples - bare.samples, line_samples, 1e-2);
  EXPECT_NEAR(creased.units() - bare.units(), (12.0 * render::kCreaseEdgeSamples + line_samples) / 1e6, 1e-9);
  EXPECT_NE(creased.describe().find("crease edges"), std::string::npos);
  // Four times the pixels: the same edges, twice the line's length.
  const render::RenderCost larger = priced(params_with_size(p, 512));
  EXPECT_EQ(larger.crease_edges, 12.0);
  EXPECT_NEAR(larger.samples - priced(params_with_size(never, 512)).samples, 2 * line_samples, 1e-2);
  p.msaa = 1;
  never.msaa = 1;
  EXPECT_NEAR(priced(p).framebuffer - priced(never).framebuffer, 2.0 * render::kLineCoveragePassSamples * 256 * 256,
              1e-6);
}

// A width in world units is priced at the pixels the framing gives it: the
// unit cube fills about 0.88 of a 512² frame across its 1.2–1.7 units seen
// obliquely, some 260–380 px a unit, so a 0.05 line is 13–19 px wide and
// its walks reach 11–15 px (were the width taken as pixels, 1).
TEST(RenderCost, AWorldWidthIsPricedAtItsPixels) {
  const scene::Model m = scene::import_obj_bundle(make_bundle({{"a.obj", kCube}}));
  render::RenderParams p = params_at(512, 512, 1);
  p.outline.edges = true;
  p.outline.units = render::OutlineUnits::World;
  p.outline.width = 0.05f;
  // The plan converts the width at its camera, and prices what it will draw.
  const render::FramePlan plan = render::plan_frame(p, std::vector<render::PlannedObject>{{m}});
  const double per_pixel = plan.cost.edge_texels / (512.0 * 512);
  const double reach = (per_pixel - render::kSilhouettePixelTexels) / 4;
  EXPECT_GE(reach, 11.0);
  EXPECT_LE(reach, 15.0);
  EXPECT_EQ(reach, std::floor(reach));
}

TEST(RenderCost, OneFigureWeighsTheThree) {
  render::RenderCost c;
  c.samples = 1e6;
  c.triangles = 1e6;
  c.tiles = 1e3;
  EXPECT_NEAR(c.units(), 1 + render::kTriangleSamples + 1e3 * render::kTileSamples / 1e6, 1e-9);
  EXPECT_NE(c.describe().find("Msamples"), std::string::npos);
}

}  // namespace
}  // namespace toond
