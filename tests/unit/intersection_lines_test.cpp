// Where separate parts of a model pass through each other
// (scene/mesh/intersection_lines.h): the seams import finds, on clean and on
// messy input (split copies of vertices, near-duplicates, seams cut into
// pieces by the triangles of both parts), the contacts that make no line
// (boxes stacked flush, faces lying on faces) and the one that does (a
// block standing on a floor), and the search giving up at its budget or
// its deadline, which the pass plan answers with the screen-space pass.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "model_checks.h"
#include "render/plan/frame_plan.h"
#include "render/plan/intersections_known.h"
#include "render/plan/render_params.h"
#include "scene/animation/pose.h"
#include "scene/import/bundle_import.h"
#include "scene/import/demo_model.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/crease_edges.h"
#include "scene/mesh/intersection_lines.h"
#include "support/in_process_render.h"
#include "support/shared_models.h"

namespace toond::scene {
namespace {

// Triangles as a test builds them: each shape's vertices its own.
struct Soup {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;

  void quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const auto first = static_cast<std::uint32_t>(positions.size());
    for (const glm::vec3& p : {a, b, c, d}) {
      positions.push_back(p);
      normals.push_back(n);
    }
    indices.insert(indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }

  // A box from `low` to `high`, faces wound outward, each face its own
  // four vertices (split copies along every edge, as a flat-shaded export
  // writes them).
  void box(glm::vec3 low, glm::vec3 high) {
    const auto at = [&](int i, int j, int k) {
      return glm::vec3(i ? high.x : low.x, j ? high.y : low.y, k ? high.z : low.z);
    };
    quad(at(0, 0, 0), at(0, 0, 1), at(0, 1, 1), at(0, 1, 0));
    quad(at(1, 0, 0), at(1, 1, 0), at(1, 1, 1), at(1, 0, 1));
    quad(at(0, 0, 0), at(1, 0, 0), at(1, 0, 1), at(0, 0, 1));
    quad(at(0, 1, 0), at(0, 1, 1), at(1, 1, 1), at(1, 1, 0));
    quad(at(0, 0, 0), at(0, 1, 0), at(1, 1, 0), at(1, 0, 0));
    quad(at(0, 0, 1), at(1, 0, 1), at(1, 1, 1), at(0, 1, 1));
  }

  // Every position moved by one float step up on each axis: as near as
  // two points can be without being one.
  void nudge_from(std::size_t first) {
    const float up = std::numeric_limits<float>::infinity();
    for (std::size_t v = first; v < positions.size(); ++v) {
      glm::vec3& p = positions[v];
      p = {std::nextafter(p.x, up), std::nextafter(p.y, up), std::nextafter(p.z, up)};
    }
  }

  // A floor: a square at height y, `cells` × `cells` quads, facing up.
  void floor(float half, float y, int cells) {
    for (int i = 0; i < cells; ++i) {
      for (int k = 0; k < cells; ++k) {
        const float x0 = -half + 2 * half * i / cells, x1 = -half + 2 * half * (i + 1) / cells;
        const float z0 = -half + 2 * half * k / cells, z1 = -half + 2 * half * (k + 1) / cells;
        quad({x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0});
      }
    }
  }

  // A UV sphere, smooth, its vertices split along the meridian where u
  // wraps (the column at u = 0 is written twice, as a textured export
  // writes it).
  void sphere(glm::vec3 centre, float radius, int segments, int rings) {
    const auto first = static_cast<std::uint32_t>(positions.size());
    const double pi = std::numbers::pi;
    for (int r = 0; r <= rings; ++r) {
      for (int s = 0; s <= segments; ++s) {
        const double polar = pi * r / rings, around = 2 * pi * (s % segments) / segments;
        const glm::vec3 n(std::sin(polar) * std::cos(around), std::cos(polar), std::sin(polar) * std::sin(around));
        positions.push_back(centre + radius * n);
        normals.push_back(n);
      }
    }
    const auto at = [&](int r, int s) { return first + static_cast<std::uint32_t>(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r) {
      for (int s = 0; s < segments; ++s) {
        indices.insert(indices.end(),
                       {at(r, s), at(r, s + 1), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r + 1, s)});
      }
    }
  }
};

struct Found {
  std::uint32_t parts = 0;
  IntersectionLines lines;
};

Found search(const Soup& soup, const IntersectionSearch& options = {}) {
  Found found;
  const std::vector<std::uint32_t> part_of_vertex = label_parts(soup.positions, soup.indices, found.parts);
  found.lines = find_intersection_lines(soup.positions, soup.normals, soup.indices, part_of_vertex, options);
  return found;
}

// A search that gave up keeps nothing.
void expect_gave_up(const Found& found) {
  EXPECT_FALSE(found.lines.complete);
  EXPECT_EQ(found.lines.size(), 0u);
}

double total_length(const IntersectionLines& lines) {
  double length = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    length += glm::distance(glm::dvec3(lines.points[4 * i + 1]), glm::dvec3(lines.points[4 * i + 2]));
  }
  return length;
}

// How many segment ends meet no other segment's end (within `near`): none
// for seams that close round.
std::size_t loose_ends(const IntersectionLines& lines, double near) {
  std::size_t loose = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (int end = 1; end <= 2; ++end) {
      const glm::dvec3 p(lines.points[4 * i + end]);
      bool met = false;
      for (std::size_t j = 0; j < lines.size() && !met; ++j) {
        if (j == i) continue;
        met = glm::distance(p, glm::dvec3(lines.points[4 * j + 1])) < near ||
              glm::distance(p, glm::dvec3(lines.points[4 * j + 2])) < near;
      }
      loose += !met;
    }
  }
  return loose;
}

// The demo model (scene/import/demo_model.cpp): a sphere of radius 0.6 centred
// 0.95 above the floor, sunk 0.05 into a box 0.4 high. Where they cross is
// a circle on the box's top of radius √(0.6² − 0.55²), the polygon the
// sphere's facets cut from it; the surfaces meet there at a sharp wedge.
TEST(IntersectionLines, TheDemoSphereMeetsItsBoxInACircle) {
  Model demo = import_obj_bundle(make_demo_bundle());
  find_intersection_lines(demo.mesh);
  const IntersectionLines& lines = demo.mesh.intersections;
  EXPECT_EQ(demo.mesh.parts, 2u);
  ASSERT_TRUE(lines.complete);
  ASSERT_GE(lines.size(), 48u);
  const double radius = std::sqrt(0.6 * 0.6 - 0.55 * 0.55);
  const glm::dvec3 origin(demo.mesh.origin);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (int end = 1; end <= 2; ++end) {
      const glm::dvec3 p = origin + glm::dvec3(lines.points[4 * i + end]);
      EXPECT_NEAR(p.y, 0.4, 1e-5);
      EXPECT_NEAR(std::hypot(p.x, p.z), radius, 0.01 * radius);
    }
  }
  EXPECT_NEAR(total_length(lines), 2 * std::numbers::pi * radius, 0.02 * 2 * std::numbers::pi * radius);
  EXPECT_EQ(loose_ends(lines, 1e-5), 0u);
  EXPECT_EQ(lines.creased_at(90), lines.size()) << "the wedge is sharp: every segment turns by more than 90°";
  for (const MeshLod& lod : demo.mesh.lods) {
    EXPECT_TRUE(lod.intersections.complete);
    EXPECT_GT(lod.intersections.size(), 0u) << "a coarser level's sphere still sinks into the box";
  }
}

// A sphere whose vertices are split along a meridian, sunk into a floor of
// many quads: one part, not two, and its seam a closed chain of segments
// cut wherever a triangle edge of either part crosses it, as long as the
// circle it follows.
TEST(IntersectionLines, ASeamCutIntoPiecesStillClosesRound) {
  Soup soup;
  soup.floor(2.0f, 0.0f, 8);
  soup.sphere({0.1f, 0.7f, -0.05f}, 1.0f, 40, 20);
  const Found found = search(soup);
  EXPECT_EQ(found.parts, 2u) << "the sphere's split copies are one part with it";
  ASSERT_TRUE(found.lines.complete);
  const double radius = std::sqrt(1.0 - 0.7 * 0.7);
  EXPECT_GT(found.lines.size(), 40u);
  EXPECT_NEAR(total_length(found.lines), 2 * std::numbers::pi * radius, 0.02 * 2 * std::numbers::pi * radius);
  EXPECT_EQ(loose_ends(found.lines, 1e-5), 0u);
}

// Near-duplicate vertices (each face's corners up to five float steps off
// the others', unwelded: six parts) touch only at their rims: no
// line. Boxes stacked flush, and set side by side face to face, a float
// step apart (separate objects, as an exporter writes them; exactly on one
// another they would share corners and be one part), meet in areas and at
// rims: no line either.
TEST(IntersectionLines, TouchingWithoutCrossingMakesNoLine) {
  Soup jittered;
  jittered.box({-1, -1, -1}, {1, 1, 1});
  for (std::size_t face = 1; face < 6; ++face) jittered.nudge_from(4 * face);
  const Found apart = search(jittered);
  EXPECT_EQ(apart.parts, 6u);
  EXPECT_TRUE(apart.lines.complete);
  EXPECT_EQ(apart.lines.size(), 0u);

  Soup stacked;
  stacked.box({-1, 0, -1}, {1, 1, 1});
  stacked.box({-1, 1, -1}, {1, 2, 1});
  stacked.nudge_from(24);
  const Found flush = search(stacked);
  EXPECT_EQ(flush.parts, 2u);
  EXPECT_EQ(flush.lines.size(), 0u);

  Soup beside;
  beside.box({-1, 0, -1}, {0, 1, 1});
  beside.box({0, 0, -1}, {1, 1, 1});
  beside.nudge_from(24);
  const Found face_to_face = search(beside);
  EXPECT_EQ(face_to_face.parts, 2u);
  EXPECT_EQ(face_to_face.lines.size(), 0u);
}

// A block standing on a floor (its bottom in the floor's plane) meets it
// in a concave fold all round its foot, though neither crosses the other:
// a line as long as the foot's rim, every segment turning 90°.
TEST(IntersectionLines, ABlockStandingOnAFloorMakesOne) {
  Soup soup;
  soup.floor(2.0f, 0.0f, 3);
  soup.box({-0.5f, 0.0f, -0.3f}, {0.4f, 1.0f, 0.6f});
  const Found found = search(soup);
  EXPECT_EQ(found.parts, 2u);
  ASSERT_TRUE(found.lines.complete);
  EXPECT_NEAR(total_length(found.lines), 2 * (0.9 + 0.9), 1e-5);
  EXPECT_EQ(loose_ends(found.lines, 1e-6), 0u);
  EXPECT_EQ(found.lines.creased_at(89), found.lines.size());
  EXPECT_EQ(found.lines.creased_at(91), 0u);
}

// Through import: the same block and floor written with near-duplicate
// corners are welded into one point each; the floor's split quads stay one
// part; the line is found the same.
TEST(IntersectionLines, ImportWeldsNearDuplicatesBeforeTheSearch) {
  std::string obj;
  Soup soup;
  soup.floor(2.0f, 0.0f, 3);
  soup.box({-0.5f, 0.0f, -0.3f}, {0.4f, 1.0f, 0.6f});
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    const glm::vec3 p = soup.positions[v] + 1e-7f * static_cast<float>(v % 4);
    obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  for (std::size_t i = 0; i < soup.indices.size(); i += 3) {
    obj += "f " + std::to_string(soup.indices[i] + 1) + " " + std::to_string(soup.indices[i + 1] + 1) + " " +
           std::to_string(soup.indices[i + 2] + 1) + "\n";
  }
  Bundle bundle;
  bundle.add("m.obj", obj);
  Model model = import_obj_bundle(bundle);
  find_intersection_lines(model.mesh);
  EXPECT_EQ(model.mesh.parts, 2u);
  ASSERT_TRUE(model.mesh.intersections.complete);
  EXPECT_NEAR(total_length(model.mesh.intersections), 3.6, 1e-4);
}

// Forty copies of a grid of 16 × 16 quads, each a ten-millionth above the
// last (within the search's tolerance: one plane): every triangle's box
// overlaps those of every other copy, none crosses another.
// Past its budget the search gives up and keeps nothing; with one large
// enough it sees them through.
TEST(IntersectionLines, TheSearchGivesUpPastItsBudget) {
  Soup soup;
  for (int copy = 0; copy < 40; ++copy) soup.floor(1.0f, 1e-7f * static_cast<float>(copy), 16);
  IntersectionSearch tight;
  tight.work_per_triangle = 8;
  const Found gave_up = search(soup, tight);
  EXPECT_EQ(gave_up.parts, 40u);
  expect_gave_up(gave_up);
  IntersectionSearch ample;
  ample.work_per_triangle = 1e6;
  const Found through = search(soup, ample);
  EXPECT_TRUE(through.lines.complete);
  EXPECT_EQ(through.lines.size(), 0u);
}

// Thirty strips of two triangles along x woven through thirty along z, a
// pair of triangles crossing at every one of 900 places: more seams than
// four a triangle, past what the search keeps; allowed more, it keeps
// them all, one a crossing (each cut in pieces by the triangles'
// diagonals, joined again).
TEST(IntersectionLines, TheSearchGivesUpPastTheSegmentsItKeeps) {
  Soup soup;
  for (int i = 0; i < 30; ++i) {
    const float at = -1.5f + 0.1f * static_cast<float>(i);
    const float lift = 0.02f * static_cast<float>(i % 2);
    soup.quad({-1.6f, lift - 0.05f, at}, {-1.6f, lift + 0.05f, at + 0.01f}, {1.6f, lift + 0.05f, at + 0.01f},
              {1.6f, lift - 0.05f, at});
    soup.quad({at, -0.05f, -1.6f}, {at, -0.05f, 1.6f}, {at + 0.01f, 0.05f, 1.6f}, {at + 0.01f, 0.05f, -1.6f});
  }
  const Found kept_too_many = search(soup);
  EXPECT_EQ(kept_too_many.parts, 60u);
  expect_gave_up(kept_too_many);
  IntersectionSearch more;
  more.segments_per_triangle = 100;
  const Found all = search(soup, more);
  EXPECT_TRUE(all.lines.complete);
  EXPECT_EQ(all.lines.size(), 900u) << "one a crossing, its pieces joined";
}

// Past its deadline (the import's), the search gives up at once, even on a
// mesh small enough never to run out of budget.
TEST(IntersectionLines, TheSearchGivesUpAtItsDeadline) {
  Model demo = import_obj_bundle(make_demo_bundle());
  IntersectionSearch late;
  late.deadline = std::chrono::steady_clock::now() - std::chrono::milliseconds(1);
  find_intersection_lines(demo.mesh, late);
  EXPECT_EQ(demo.mesh.parts, 2u);
  EXPECT_FALSE(demo.mesh.intersections.complete);
  EXPECT_EQ(demo.mesh.intersections.size(), 0u);
  for (const MeshLod& lod : demo.mesh.lods) EXPECT_FALSE(lod.intersections.complete);
}

// Minetest's player (Debian's game data, tests/exported/minetest), its
// boxes pushed into one another, posed at a frame of its walk: every end
// of every seam found for the pose lies on the posed surfaces of two of
// its parts; of the seams found at rest, carried into the pose by either
// part they lie on, some ends land apart (the parts slid along each
// other): drawn as they are, they would not be where the parts cross.
TEST(IntersectionLines, APosesSeamsLieOnTwoPartsInThatPose) {
  setenv("TOOND_ASSIMP_CONVERTER", TOOND_ASSIMP_CONVERTER_PATH, 1);
  const std::filesystem::path folder = std::filesystem::path(TOOND_EXPORTED_DIR) / "minetest";
  const Model player =
      import_bundle(test_checks::make_bundle({{"character.b3d", test::read_file(folder / "character.b3d")}}));
  ASSERT_TRUE(player.rig);
  const Mesh& mesh = player.mesh;
  const Rig& rig = *player.rig;
  const NodePose walking = pose_nodes(rig, &rig.clips[0], 177.0 / 60.0);
  const SkinPose pose = skin_pose(mesh, rig, walking);
  const PosedVertices posed = pose_vertices(mesh, rig, walking);
  std::uint32_t parts = 0;
  const std::vector<std::uint32_t> part_of = label_parts(mesh.positions, mesh.indices, parts);
  ASSERT_EQ(parts, mesh.parts);
  ASSERT_GT(parts, 1u);
  const double diagonal = glm::distance(glm::dvec3(posed.bounds.min), glm::dvec3(posed.bounds.max));
  // Each part whose triangle (in `at`) holds `p` within a millionth of the
  // model, and where that triangle carries p in the pose.
  const auto holding = [&](const std::vector<glm::vec3>& at, const glm::dvec3& p) {
    std::vector<std::pair<std::uint32_t, glm::dvec3>> found;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
      const std::uint32_t v[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
      const glm::dvec3 a(at[v[0]]), b(at[v[1]]), c(at[v[2]]);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double area = glm::length(n);
      if (area <= 0.0 || std::abs(glm::dot(p - a, n / area)) > 1e-6 * diagonal) continue;
      const double wa = glm::dot(glm::cross(c - b, p - b), n) / (area * area);
      const double wb = glm::dot(glm::cross(a - c, p - c), n) / (area * area);
      if (wa < -1e-6 || wb < -1e-6 || wa + wb > 1 + 1e-6) continue;
      if (std::any_of(found.begin(), found.end(), [&](const auto& f) { return f.first == part_of[v[0]]; })) continue;
      const glm::dvec3 carried = wa * glm::dvec3(posed.positions[v[0]]) + wb * glm::dvec3(posed.positions[v[1]]) +
                                 (1 - wa - wb) * glm::dvec3(posed.positions[v[2]]);
      found.emplace_back(part_of[v[0]], carried);
    }
    return found;
  };
  const IntersectionLines& now = pose.intersections.at(0);
  ASSERT_TRUE(now.complete);
  ASSERT_GT(now.size(), 0u);
  for (std::size_t s = 0; s < now.size(); ++s) {
    for (int end = 1; end <= 2; ++end) {
      EXPECT_GE(holding(posed.positions, glm::dvec3(now.points[4 * s + end])).size(), 2u) << "segment " << s;
    }
  }
  std::size_t ends = 0, apart = 0;
  for (std::size_t s = 0; s < mesh.intersections.size(); ++s) {
    for (int end = 1; end <= 2; ++end) {
      const auto carried = holding(mesh.positions, glm::dvec3(mesh.intersections.points[4 * s + end]));
      if (carried.size() < 2) continue;
      ++ends;
      apart += glm::distance(carried[0].second, carried[1].second) > 0.005 * diagonal;
    }
  }
  std::printf(
      "[seams] minetest player walking: %zu seam segments in the pose, %zu at rest; of %zu rest seam ends, "
      "%zu land more than 0.5 %% of the model apart carried by either part\n",
      now.size(), mesh.intersections.size(), ends, apart);
  EXPECT_GT(ends, 0u);
  EXPECT_GT(apart, 0u);
}

// A smooth sphere is one part: nothing to search, no line.
TEST(IntersectionLines, OnePartSearchesNothing) {
  Soup soup;
  soup.sphere({0, 0, 0}, 1.0f, 32, 16);
  Mesh mesh;
  mesh.positions = soup.positions;
  mesh.normals = soup.normals;
  mesh.indices = soup.indices;
  find_intersection_lines(mesh);
  EXPECT_EQ(mesh.parts, 1u);
  EXPECT_TRUE(mesh.intersections.complete);
  EXPECT_EQ(mesh.intersections.size(), 0u);
}

}  // namespace
}  // namespace toond::scene

namespace toond::render {
namespace {

// The plan draws the demo's seam with the crease pass where import found
// it all; where the search gave up (at rest or in the pose), or a pose was
// not searched, or two objects' boxes overlap, the edge pass finds the
// lines in screen space instead.
TEST(IntersectionPlan, TheScreenSpacePassTakesOverWhereTheSegmentsAreNotAll) {
  scene::Model demo = scene::import_obj_bundle(scene::make_demo_bundle());
  scene::find_crease_edges(demo.mesh);
  scene::find_intersection_lines(demo.mesh);
  const RenderParams params = test::complete_params({{"width", 256}, {"height", 256}});
  const std::vector<PlannedObject> alone = {{demo}};
  EXPECT_EQ(plan_frame(params, alone).passes.describe(), "main,hull_outline,creases,resolve,readback");

  scene::Model gave_up = demo;
  scene::IntersectionSearch late;
  late.deadline = std::chrono::steady_clock::now() - std::chrono::milliseconds(1);
  scene::find_intersection_lines(gave_up.mesh, late);
  const std::vector<PlannedObject> unsearched = {{gave_up}};
  EXPECT_FALSE(intersections_known(unsearched));
  EXPECT_EQ(plan_frame(params, unsearched).passes.describe(),
            "main,hull_outline,edge_prepass,edges(creases),resolve,readback");

  // Posed, its parts may cross elsewhere than at rest: known where the
  // pose was searched (skin_pose does it), not where it was not.
  scene::Model rigged = demo;
  rigged.rig = std::make_shared<const scene::Rig>();
  const scene::SkinPose pose_not_searched;
  const std::vector<PlannedObject> posed = {{rigged, glm::dmat4(1.0), &pose_not_searched}};
  EXPECT_FALSE(intersections_known(posed));
  scene::SkinPose searched;
  searched.intersections.push_back(demo.mesh.intersections);
  for (const scene::MeshLod& lod : demo.mesh.lods) searched.intersections.push_back(lod.intersections);
  const std::vector<PlannedObject> posed_and_searched = {{rigged, glm::dmat4(1.0), &searched}};
  EXPECT_TRUE(intersections_known(posed_and_searched));
  searched.intersections.back().complete = false;
  EXPECT_FALSE(intersections_known(posed_and_searched));
  const std::vector<PlannedObject> at_rest = {{rigged}};
  EXPECT_TRUE(intersections_known(at_rest));

  const std::vector<PlannedObject> apart = {{demo, glm::translate(glm::dmat4(1.0), {-2.0, 0.0, 0.0})},
                                            {demo, glm::translate(glm::dmat4(1.0), {2.0, 0.0, 0.0})}};
  EXPECT_TRUE(intersections_known(apart));
  const std::vector<PlannedObject> overlapping = {{demo, glm::translate(glm::dmat4(1.0), {-0.5, 0.0, 0.0})},
                                                  {demo, glm::translate(glm::dmat4(1.0), {0.5, 0.0, 0.0})}};
  EXPECT_FALSE(intersections_known(overlapping));
}

}  // namespace
}  // namespace toond::render
