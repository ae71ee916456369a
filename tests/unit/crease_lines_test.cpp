// Crease lines drawn along the crease edges (render/passes/crease_pass.cpp)
// against what they replace and against the geometry: they cover most of
// what the screen-space edge pass drew on the shared windmill, hidden
// creases stay hidden, a view whose creases all turn away draws no edge,
// and a line is the requested width along its whole length, convex or
// concave, with its joins darkened once. In process, on the test's GL
// context, from the request a user would send.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "image/float_image.h"
#include "image/srgb.h"
#include "model_checks.h"
#include "render/plan/frame_plan.h"
#include "scene/animation/pose.h"
#include "scene/import/bundle_import.h"
#include "scene/store/model_library.h"
#include "scene/store/model_store.h"
#include "support/gl_context_test.h"
#include "support/in_process_render.h"
#include "support/shared_models.h"

namespace toond::render {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

scene::Model model_of_obj(const std::string& obj) {
  return scene::import_bundle(scene::test_checks::make_bundle({{"m.obj", obj}}));
}

double linear(std::uint8_t byte) { return image::srgb_to_linear_table()[byte]; }

double luminance(const image::Image& img, int x, int y) {
  const std::uint8_t* p = img.pixel(x, y);
  return 0.2126 * linear(p[0]) + 0.7152 * linear(p[1]) + 0.0722 * linear(p[2]);
}

// How much of a pixel a line of luminance `line` covers, from the render
// without lines (`bare`) and with (`lined`); nothing where the two are too
// alike in the bare render for a line to show.
double line_share(const image::Image& bare, const image::Image& lined, int x, int y, double line) {
  const double room = luminance(bare, x, y) - line;
  if (room < 0.02) return 0.0;
  return (luminance(bare, x, y) - luminance(lined, x, y)) / room;
}

class CreaseLines : public test::GlContextTest {};

// The shared windmill, as its OBJ, MTL and textures upload.
scene::Model shared_windmill() {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& entry : fs::directory_iterator(test::shared_models_dir() / "windmill")) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".obj" || ext == ".mtl" || ext == ".jpg")
      files.emplace_back(entry.path().filename().string(), test::read_file(entry.path()));
  }
  return scene::import_bundle(scene::test_checks::make_bundle(files));
}

// The windmill's default frame at 512²: the inner pixels the screen-space
// pass darkened by a quarter of the line or more, and how many of them the
// lines along the crease edges darken as much. What they do not draw are
// mostly the lines the screen-space pass found where one part of the model
// lies in front of another (no crease edge runs there). Measured 0.82 of
// 4,222 pixels with the seams where its 138 parts cross
// (scene/mesh/intersection_lines.h), 0.79 without.
constexpr double kLeastShareOfScreenSpaceLines = 0.6;

TEST_F(CreaseLines, TheWindmillsLinesCoverMostOfWhatTheScreenSpacePassDrew) {
  TOOND_REQUIRE_SHARED_MODELS();
  const scene::Model windmill = shared_windmill();
  test::InProcessScene scene({{&windmill, glm::dmat4(1.0)}});
  const json request = {{"width", 512}, {"height", 512}};
  RenderParams never = test::complete_params(request);
  never.outline.creases = OutlineCreases::Never;
  RenderParams screen_space = test::complete_params(request);
  screen_space.outline.screen_space_creases = true;
  const RenderOutput bare = scene.render(never);
  const RenderOutput by_pixels = scene.render(screen_space);
  const RenderOutput by_edges = scene.render(test::complete_params(request));
  ASSERT_EQ(by_pixels.plan, "main,hull_outline,edge_prepass,edges(creases),resolve,readback");
  ASSERT_EQ(by_edges.plan, "main,hull_outline,creases,resolve,readback");
  // The outline's colour, sRGB (15, 13, 20).
  const double line = 0.2126 * linear(15) + 0.7152 * linear(13) + 0.0722 * linear(20);
  std::size_t screen_space_lines = 0, covered = 0, edge_lines = 0;
  for (int y = 0; y < 512; ++y) {
    for (int x = 0; x < 512; ++x) {
      const bool old_line = line_share(bare.image, by_pixels.image, x, y, line) >= 0.25;
      const bool new_line = line_share(bare.image, by_edges.image, x, y, line) >= 0.25;
      screen_space_lines += old_line;
      covered += old_line && new_line;
      edge_lines += new_line;
    }
  }
  ASSERT_GT(screen_space_lines, 1000u);
  const double share = static_cast<double>(covered) / static_cast<double>(screen_space_lines);
  std::printf(
      "[creases] windmill: the screen-space pass darkened %zu inner pixels, the crease lines %.3f of them "
      "(%zu line pixels in all, %zu crease edges and %zu seam segments drawn)\n",
      screen_space_lines, share, edge_lines, by_edges.crease_edges_drawn, by_edges.intersection_segments_drawn);
  EXPECT_GE(share, kLeastShareOfScreenSpaceLines);
}

// The pixels a line darkens in `lined` by a quarter of the line or more,
// against the same frame without lines (`bare`), in the outline's colour
// (sRGB (15, 13, 20)).
std::vector<bool> line_pixels(const image::Image& bare, const image::Image& lined) {
  const double line = 0.2126 * linear(15) + 0.7152 * linear(13) + 0.0722 * linear(20);
  std::vector<bool> lines(static_cast<std::size_t>(bare.width) * bare.height);
  for (int y = 0; y < bare.height; ++y) {
    for (int x = 0; x < bare.width; ++x) {
      lines[static_cast<std::size_t>(y) * bare.width + x] = line_share(bare, lined, x, y, line) >= 0.25;
    }
  }
  return lines;
}

// Where a model's parts meet, against the screen-space pass: the pixels
// it darkened along the stretches of the seams that show (points along the
// seams, in the mesh's coordinates, projected into the default frame and
// kept where the depth layer puts no surface in front of them), and how
// many of those the default frame darkens, and how many the crease edges
// alone would (the model without its seams).
struct ContactLines {
  std::size_t contact = 0;  // screen-space line pixels within a pixel of a visible seam point
  double drawn = 0;         // the share of them the default frame darkens
  double edges_alone = 0;   // the share the crease edges alone darken
  std::size_t segments_drawn = 0;
  std::string plan;
};

ContactLines contact_lines(const scene::Model& model, const std::vector<glm::dvec3>& seam, const json& request,
                           std::shared_ptr<const scene::SkinPose> pose = nullptr) {
  scene::Model without_seams = model;
  without_seams.mesh.intersections = {};
  for (scene::MeshLod& lod : without_seams.mesh.lods) lod.intersections = {};
  test::InProcessScene scene({{&model, glm::dmat4(1.0)}});
  test::InProcessScene edges_alone({{&without_seams, glm::dmat4(1.0)}});
  scene.pose(0, pose);
  if (pose) {
    auto pose_without_seams = std::make_shared<scene::SkinPose>(*pose);
    for (scene::IntersectionLines& lines : pose_without_seams->intersections) lines = {};
    edges_alone.pose(0, pose_without_seams);
  }
  const RenderParams params = test::complete_params(request);
  RenderParams never = params;
  never.outline.creases = OutlineCreases::Never;
  RenderParams screen_space = params;
  screen_space.outline.screen_space_creases = true;
  json depth_request = request;
  depth_request["output"] = "depth";
  const image::FloatImage depth = scene.render(test::complete_params(depth_request)).layer;
  const image::Image bare = scene.render(never).image;
  const std::vector<bool> old_lines = line_pixels(bare, scene.render(screen_space).image);
  const std::vector<bool> edge_lines = line_pixels(bare, edges_alone.render(params).image);
  const RenderOutput drawn = scene.render(params);
  const std::vector<bool> new_lines = line_pixels(bare, drawn.image);

  const std::vector<PlannedObject> objects = {{model, glm::dmat4(1.0), pose.get()}};
  const FramePlan plan = plan_frame(params, objects);
  const glm::dmat4 clip = plan.camera.projection * plan.camera.view * plan.scene->matrices[0];
  const int width = bare.width, height = bare.height;
  std::vector<bool> near_seam(old_lines.size());
  for (const glm::dvec3& point : seam) {
    const glm::dvec4 c = clip * glm::dvec4(point, 1.0);
    const int x = static_cast<int>(std::floor((c.x / c.w * 0.5 + 0.5) * width));
    const int y = static_cast<int>(std::floor((0.5 - c.y / c.w * 0.5) * height));
    if (x < 1 || y < 1 || x >= width - 1 || y >= height - 1 || !depth.covered(x, y)) continue;
    // The depth layer is the distance along the view axis, as w is; a
    // surface seen at a grazing angle changes it by a few pixels' widths
    // from one pixel to the next.
    const double pixel = 2.0 * c.w / (plan.camera.projection[1][1] * height);
    if (c.w > depth.pixel(x, y)[0] + 8.0 * pixel) continue;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) near_seam[static_cast<std::size_t>(y + dy) * width + x + dx] = true;
    }
  }
  ContactLines c;
  std::size_t drawn_there = 0, edges_there = 0;
  for (std::size_t i = 0; i < old_lines.size(); ++i) {
    if (!old_lines[i] || !near_seam[i]) continue;
    ++c.contact;
    drawn_there += new_lines[i];
    edges_there += edge_lines[i];
  }
  const double contact = static_cast<double>(std::max<std::size_t>(c.contact, 1));
  c.drawn = static_cast<double>(drawn_there) / contact;
  c.edges_alone = static_cast<double>(edges_there) / contact;
  c.segments_drawn = drawn.intersection_segments_drawn;
  c.plan = drawn.plan;
  return c;
}

// Prints what `c` measured on `model` and expects the crease pass to draw
// the seams where the screen-space pass drew lines along them.
void expect_seams_drawn(const char* model, const ContactLines& c, std::size_t least_contact) {
  std::printf(
      "[creases] %s: %zu screen-space line pixels along the seams that show, the default frame darkens "
      "%.3f of them, the crease edges alone %.3f (%zu seam segments drawn)\n",
      model, c.contact, c.drawn, c.edges_alone, c.segments_drawn);
  EXPECT_EQ(c.plan, "main,hull_outline,creases,resolve,readback");
  ASSERT_GT(c.contact, least_contact);
  EXPECT_GT(c.segments_drawn, 0u);
  EXPECT_GE(c.drawn, kLeastShareOfScreenSpaceLines);
}

// Points every hundredth of the model along every segment of `lines`.
std::vector<glm::dvec3> points_along(const scene::IntersectionLines& lines, const scene::Bounds& bounds) {
  const double step = 0.01 * glm::distance(glm::dvec3(bounds.min), glm::dvec3(bounds.max));
  std::vector<glm::dvec3> points;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const glm::dvec3 a(lines.points[4 * i + 1]), b(lines.points[4 * i + 2]);
    const int n = 1 + static_cast<int>(glm::distance(a, b) / step);
    for (int k = 0; k <= n; ++k) points.push_back(glm::mix(a, b, static_cast<double>(k) / n));
  }
  return points;
}

// The built-in demo model, as the daemon holds it, in the default frame of
// a request without a model: its sphere (radius 0.6, centre 0.95 up) sinks
// into its box (0.4 high) along a circle of radius √(0.6² − 0.55²), which
// the screen-space pass drew where it shows and no crease edge runs along.
// The circle is drawn again. Measured: 0.86 of the 140 screen-space line
// pixels along it, none with the crease edges alone. Beside it the
// screen-space pass also drew the sphere's outline where it stands in
// front of the box, which no line along an edge or a seam draws (as on
// the windmill).
TEST_F(CreaseLines, TheDemoSpheresSeamOnItsBoxIsDrawn) {
  const fs::path dir = fs::temp_directory_path() / ("toond-demo-seam-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  std::shared_ptr<const scene::Model> demo;
  {
    scene::ModelStore store(dir);
    scene::ModelLibrary library(store, 4);
    demo = library.demo();
  }
  fs::remove_all(dir);
  const double radius = std::sqrt(0.6 * 0.6 - 0.55 * 0.55);
  std::vector<glm::dvec3> circle;
  for (int i = 0; i < 2000; ++i) {
    const double around = 2.0 * std::acos(-1.0) * i / 2000;
    circle.push_back(glm::dvec3(radius * std::cos(around), 0.4, radius * std::sin(around)) -
                     glm::dvec3(demo->mesh.origin));
  }
  const ContactLines c = contact_lines(*demo, circle, {{"width", 512}, {"height", 512}});
  expect_seams_drawn("demo", c, 30u);
}

// The shared Kenney dog: its ears, eyes and snout are parts pushed into
// its head, its legs into its body. Along the seams that show (those
// import found, scene/mesh/intersection_lines.h, sampled every hundredth
// of the model), the lines come back. Measured: 0.94 of 772 pixels, 0.03
// with the crease edges alone.
TEST_F(CreaseLines, TheKenneyDogsSeamsAreDrawn) {
  TOOND_REQUIRE_SHARED_MODELS();
  std::vector<std::pair<std::string, std::string>> files;
  const fs::path folder = test::shared_models_dir() / "kenney-cube-pet-dog";
  files.emplace_back("animal-dog.obj", test::read_file(folder / "animal-dog.obj"));
  files.emplace_back("animal-dog.mtl", test::read_file(folder / "animal-dog.mtl"));
  files.emplace_back("Textures/colormap.png", test::read_file(folder / "Textures" / "colormap.png"));
  const scene::Model dog = scene::import_bundle(scene::test_checks::make_bundle(files));
  const scene::IntersectionLines& lines = dog.mesh.intersections;
  ASSERT_GT(dog.mesh.parts, 1u);
  ASSERT_TRUE(lines.complete);
  ASSERT_GT(lines.size(), 0u);
  const ContactLines c = contact_lines(dog, points_along(lines, dog.mesh.bounds), {{"width", 512}, {"height", 512}});
  expect_seams_drawn("kenney dog", c, 100u);
}

// Minetest's player (Debian's game data, tests/exported/minetest): head,
// body and limbs are boxes pushed into one another, and walking they swing
// through each other. Posed at a frame of its walk, its seams are where
// the parts cross in that pose (found for the pose, scene::SkinPose::
// intersections), drawn by the crease pass: where the screen-space pass
// drew lines along them, the default frame draws them too, with the crease
// pass (before, a posed model's frame fell back to the screen-space pass,
// 7.8 times its frame without lines, docs/performance.md). Measured: 0.91
// of 33 pixels; 0.70 with the crease edges alone, since most of what shows
// of its seams from here runs beside box edges (where the seams lie is
// checked by IntersectionLines.APosesSeamsLieOnTwoPartsInThatPose).
TEST_F(CreaseLines, APosedModelsSeamsAreWhereItsPartsCrossInThePose) {
  setenv("TOOND_ASSIMP_CONVERTER", TOOND_ASSIMP_CONVERTER_PATH, 1);
  const fs::path folder = fs::path(TOOND_EXPORTED_DIR) / "minetest";
  const scene::Model player = scene::import_bundle(
      scene::test_checks::make_bundle({{"character.b3d", test::read_file(folder / "character.b3d")},
                                       {"character.png", test::read_file(folder / "character.png")}}));
  ASSERT_TRUE(player.rig);
  ASSERT_GT(player.mesh.parts, 1u);
  const scene::Rig& rig = *player.rig;
  const double walking = 177.0 / 60.0;  // frame 177 of the walk (frames 168-187 at 60 a second)
  auto pose = std::make_shared<scene::SkinPose>(
      scene::skin_pose(player.mesh, rig, scene::pose_nodes(rig, &rig.clips[0], walking)));
  // Framed by this one pose, so the player fills the frame.
  const scene::ClipFraming framing = scene::frame_clip(player.mesh, rig, 0, {walking, walking});
  pose->bounds = framing.bounds;
  pose->extremes = framing.extremes;
  ASSERT_EQ(pose->intersections.size(), 1 + player.mesh.lods.size());
  ASSERT_TRUE(pose->intersections[0].complete);
  ASSERT_GT(pose->intersections[0].size(), 0u);
  // Drawn opaque: as Minetest draws it, its hat layer is a mask, and
  // masked materials find their crease lines in screen space.
  const ContactLines c =
      contact_lines(player, points_along(pose->intersections[0], framing.bounds),
                    {{"width", 512}, {"height", 512}, {"materials", {{"Character", {{"alpha", "opaque"}}}}}}, pose);
  expect_seams_drawn("minetest player walking", c, 30u);
}

// OBJ text of a flat-shaded box: half sizes `half`, centred at `centre`,
// turned by `yaw_deg` about y; `first` is the OBJ index of its first vertex.
std::string flat_box_obj(glm::dvec3 half, glm::dvec3 centre, double yaw_deg, int first) {
  const glm::dmat4 place = glm::rotate(glm::translate(glm::dmat4(1.0), centre), glm::radians(yaw_deg), {0, 1, 0});
  std::string obj;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 p =
        place * glm::dvec4((i & 1) ? half.x : -half.x, (i & 2) ? half.y : -half.y, (i & 4) ? half.z : -half.z, 1.0);
    obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  // Corner (i, j, k) of x, y, z is vertex first + i + 2j + 4k; faces wound
  // outward, each its own normal (normals by angle split every edge).
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    obj += "f";
    for (const int c : f) obj += " " + std::to_string(first + c);
    obj += "\n";
  }
  return obj;
}

// A box turned toward the camera shows three faces and their crease lines;
// behind a wide square that hides it, not a pixel of them shows (the
// square has no crease of its own).
TEST_F(CreaseLines, HiddenCreasesStayHidden) {
  const std::string box = flat_box_obj({0.7, 0.7, 0.7}, {0.0, 0.0, -3.0}, 35.0, 1);
  const std::string square = "v -3 -3 0\nv 3 -3 0\nv 3 3 0\nv -3 3 0\nf 9 10 11 12\n";
  const scene::Model alone = model_of_obj(box);
  const scene::Model hidden = model_of_obj(box + square);
  for (const int msaa : {1, 4}) {
    const json request = {{"width", 160}, {"height", 160}, {"msaa", msaa}, {"camera", {{"pitch", 25}}}};
    json never = request;
    never["outline"] = {{"creases", "never"}};
    const auto differing = [](const image::Image& a, const image::Image& b) {
      std::size_t n = 0;
      for (std::size_t i = 0; i < a.rgba.size(); i += 4) n += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1];
      return n;
    };
    EXPECT_GT(differing(test::render_in_process(alone, request), test::render_in_process(alone, never)), 100u)
        << "msaa " << msaa << ": the box alone shows its crease lines";
    EXPECT_EQ(differing(test::render_in_process(hidden, request), test::render_in_process(hidden, never)), 0u)
        << "msaa " << msaa << ": behind the plate no crease line shows";
  }
}

// A UV sphere about z, smooth but for a cap round its back pole (z < -0.6),
// whose faces have a normal each: every crease lies on the back.
std::string sphere_with_faceted_back() {
  const int segments = 32, rings = 16;
  const double pi = std::acos(-1.0);
  std::string obj;
  std::vector<glm::dvec3> points;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const double polar = pi * r / rings, around = 2.0 * pi * s / segments;
      points.push_back({std::sin(polar) * std::cos(around), std::sin(polar) * std::sin(around), std::cos(polar)});
      obj += "v " + std::to_string(points.back().x) + " " + std::to_string(points.back().y) + " " +
             std::to_string(points.back().z) + "\n";
      obj += "vn " + std::to_string(points.back().x) + " " + std::to_string(points.back().y) + " " +
             std::to_string(points.back().z) + "\n";
    }
  }
  int flat_normals = 0;
  const auto index = [&](int r, int s) { return r * segments + (s % segments) + 1; };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const int quad[4] = {index(r, s), index(r + 1, s), index(r + 1, s + 1), index(r, s + 1)};
      const glm::dvec3 middle = (points[quad[0] - 1] + points[quad[1] - 1] + points[quad[2] - 1] + points[quad[3] - 1]);
      const bool back = points[quad[0] - 1].z < -0.6 || points[quad[1] - 1].z < -0.6;
      std::string face = "f";
      if (back) {
        const glm::dvec3 n = glm::normalize(middle);
        obj += "vn " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n";
        ++flat_normals;
      }
      for (const int v : quad) {
        const int normal = back ? static_cast<int>(points.size()) + flat_normals : v;
        face += " " + std::to_string(v) + "//" + std::to_string(normal);
      }
      obj += face + "\n";
    }
  }
  return obj;
}

// Seen from the front, every crease of that sphere is turned away: runs of
// them are left out before the vertex stage (render/cull/facing_runs.h), no
// edge is drawn, and the image is the one without crease lines. From the
// back they draw.
TEST_F(CreaseLines, AViewWhoseCreasesAllTurnAwayDrawsNoEdge) {
  const scene::Model sphere = model_of_obj(sphere_with_faceted_back());
  ASSERT_GT(sphere.mesh.crease_edges.creased_at(10), 0u);
  ASSERT_EQ(sphere.mesh.enclosure, scene::Enclosure::Outward);
  test::InProcessScene scene({{&sphere, glm::dmat4(1.0)}});
  const json request = {{"width", 128},
                        {"height", 128},
                        {"camera", {{"yaw", 0}, {"pitch", 0}}},
                        {"lod", "full"},
                        {"outline", {{"creases", "always"}, {"crease_angle", 10}}}};
  const RenderOutput front = scene.render(test::complete_params(request));
  EXPECT_EQ(front.plan, "main,hull_outline,creases,resolve,readback");
  EXPECT_EQ(front.crease_edges_drawn, 0u) << "of " << sphere.mesh.crease_edges.creased_at(10);
  json never = request;
  never["outline"]["creases"] = "never";
  EXPECT_TRUE(front.image.rgba == scene.render(test::complete_params(never)).image.rgba);
  json back = request;
  back["camera"] = {{"yaw", 180}, {"pitch", 0}};
  EXPECT_GT(scene.render(test::complete_params(back)).crease_edges_drawn, 0u);
}

// A ridge (two faces meeting at `turn_deg`, convex toward +z or concave)
// along x, made of `segments` lengths: its crease line is a chain of
// collinear edges, joined at every segment's end.
std::string ridge_obj(double rise, int segments) {
  std::string obj;
  for (int i = 0; i <= segments; ++i) {
    const double x = -2.0 + 4.0 * i / segments;
    // Three points across: the left foot, the ridge, the right foot.
    obj += "v " + std::to_string(x) + " -1 0\n";
    obj += "v " + std::to_string(x) + " 0.0173 " + std::to_string(rise) + "\n";
    obj += "v " + std::to_string(x) + " 1 0\n";
  }
  const glm::dvec3 left = glm::normalize(glm::dvec3(0.0, -rise, 1.0173)),
                   right = glm::normalize(glm::dvec3(0.0, rise, 0.9827));
  obj += "vn " + std::to_string(left.x) + " " + std::to_string(left.y) + " " + std::to_string(left.z) + "\n";
  obj += "vn " + std::to_string(right.x) + " " + std::to_string(right.y) + " " + std::to_string(right.z) + "\n";
  for (int i = 0; i < segments; ++i) {
    const int a = 3 * i + 1, b = a + 3;
    obj += "f " + std::to_string(a) + "//1 " + std::to_string(b) + "//1 " + std::to_string(b + 1) + "//1 " +
           std::to_string(a + 1) + "//1\n";
    obj += "f " + std::to_string(a + 1) + "//2 " + std::to_string(b + 1) + "//2 " + std::to_string(b + 2) + "//2 " +
           std::to_string(a + 2) + "//2\n";
  }
  return obj;
}

// The ridge seen from above, orthographic, white and unlit, with black
// crease lines of `width`: every pixel's darkness is the line's share of it.
json ridge_request(int size, int msaa, double width) {
  return {{"width", size},
          {"height", size},
          {"msaa", msaa},
          {"background", {1, 1, 1}},
          {"camera", {{"projection", "orthographic"}, {"yaw", 0}, {"pitch", 0}}},
          {"lights", json::array()},
          {"shading", {{"mode", "flat"}, {"base", "white"}}},
          {"specular", {{"enabled", false}}},
          {"outline", {{"width", width}, {"color", {0, 0, 0}}, {"creases", "always"}}}};
}

// Seen from above (orthographic, white and unlit, black lines), the ridge's
// crease line, measured across it column by column as the line's share of
// each pixel added up: the requested width within half a pixel in every
// column, convex or concave (a line at the edge's own depth, not in its
// faces' planes, is cut to a sliver on a concave crease), and as wide at
// the joins between its edges as between them (two round caps overlapping
// there must not darken the pixels they share twice).
TEST_F(CreaseLines, ALineIsItsWidthAlongItsLengthAndAtItsJoins) {
  const int kSegments = 8, kSize = 256;
  for (const double rise : {0.5, -0.5}) {
    const scene::Model ridge = model_of_obj(ridge_obj(rise, kSegments));
    ASSERT_EQ(ridge.mesh.crease_edges.creased_at(40), static_cast<std::size_t>(kSegments));
    for (const int msaa : {1, 4}) {
      for (const double width : {1.5, 2.0, 5.0}) {
        const image::Image img = test::render_in_process(ridge, ridge_request(kSize, msaa, width));
        // The ridge runs across the middle row; the model spans x -2..2
        // of the framed width. Columns well inside the ends.
        double worst = 0, joins = 0, between = 0;
        int join_columns = 0, between_columns = 0;
        // The model's ends: where, along a row off the ridge, the white
        // inside begins after the hull's dark ring, from either side
        // (where the silhouette crosses that pixel half way).
        const int row = kSize / 2 + 12;
        double left = -1, right = -1;
        for (int x = 1; x < kSize && left < 0; ++x) {
          const double a = luminance(img, x - 1, row), b = luminance(img, x, row);
          if (a < 0.5 && b >= 0.5) left = x - 0.5 + (0.5 - a) / (b - a);
        }
        for (int x = kSize - 2; x >= 0 && right < 0; --x) {
          const double a = luminance(img, x + 1, row), b = luminance(img, x, row);
          if (a < 0.5 && b >= 0.5) right = x + 1.5 - (0.5 - a) / (b - a);
        }
        ASSERT_GT(left, 0);
        ASSERT_GT(right, left + 100);
        const double segment_px = (right - left) / kSegments;
        for (int x = static_cast<int>(left) + 12; x <= static_cast<int>(right) - 12; ++x) {
          double measured = 0;
          for (int y = kSize / 2 - 10; y <= kSize / 2 + 10; ++y) measured += 1.0 - luminance(img, x, y);
          worst = std::max(worst, std::abs(measured - width));
          const double along = (x + 0.5 - left) / segment_px;
          if (std::abs(along - std::round(along)) * segment_px < 1.0) {
            joins += measured;
            ++join_columns;
          } else if (std::abs(along - std::round(along)) * segment_px > 4.0) {
            between += measured;
            ++between_columns;
          }
        }
        ASSERT_GT(join_columns, 0);
        ASSERT_GT(between_columns, 0);
        const double at_joins = joins / join_columns, elsewhere = between / between_columns;
        std::printf(
            "[creases] ridge rise %+.1f msaa %d width %.1f: worst error %.3f px, %.3f px at joins, %.3f "
            "between\n",
            rise, msaa, width, worst, at_joins, elsewhere);
        EXPECT_LE(worst, 0.5) << "rise " << rise << " msaa " << msaa << " width " << width;
        EXPECT_NEAR(at_joins, elsewhere, 0.1) << "rise " << rise << " msaa " << msaa << " width " << width;
      }
    }
  }
}

// The ridge turned about the view axis by `degrees`: its vertices (and
// normals) turned in the image's plane.
std::string turned_obj(const std::string& obj, double degrees) {
  const double c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
  std::string out;
  std::size_t start = 0;
  while (start < obj.size()) {
    const std::size_t end = obj.find('\n', start);
    const std::string line = obj.substr(start, end - start);
    start = end + 1;
    double x = 0, y = 0, z = 0;
    char kind[3] = {};
    if (std::sscanf(line.c_str(), "%2s %lf %lf %lf", kind, &x, &y, &z) == 4 &&
        (std::string(kind) == "v" || std::string(kind) == "vn")) {
      out += std::string(kind) + " " + std::to_string(c * x - s * y) + " " + std::to_string(s * x + c * y) + " " +
             std::to_string(z) + "\n";
    } else {
      out += line + "\n";
    }
  }
  return out;
}

// A crease line across the image at a slant is its width too, measured
// across it: a GL line drawn without multisampling spans its width along
// x or y only, not across, so the pass must draw it wider there; with
// multisampling it is a rectangle. Each column's line share, added up
// over the rows about the image's middle, is the width over cos(angle).
TEST_F(CreaseLines, ASlantedLineIsItsWidthAcrossIt) {
  const int kSegments = 8, kSize = 256;
  for (const double degrees : {30.0, 45.0}) {
    const scene::Model ridge = model_of_obj(turned_obj(ridge_obj(0.5, kSegments), degrees));
    for (const int msaa : {1, 4}) {
      for (const double width : {2.0, 5.0, 9.0}) {
        const image::Image img = test::render_in_process(ridge, ridge_request(kSize, msaa, width));
        const double slant = std::cos(glm::radians(degrees));
        double worst = 0;
        for (int x = kSize / 2 - 24; x <= kSize / 2 + 24; ++x) {
          double measured = 0;
          for (int y = kSize / 2 - 40; y <= kSize / 2 + 40; ++y) measured += 1.0 - luminance(img, x, y);
          worst = std::max(worst, std::abs(measured * slant - width));
        }
        std::printf("[creases] ridge at %.0f° msaa %d width %.1f: worst error across the line %.3f px\n", degrees, msaa,
                    width, worst);
        EXPECT_LE(worst, 0.5) << degrees << "° msaa " << msaa << " width " << width;
      }
    }
  }
}

// Where a driver's lines are too narrow the pass draws each line as a quad:
// the same samples are written, since the fragment stage trims either to
// the line's own width and caps. The windmill's default frame (crease
// edges and seams) at one sample and four, and the slanted ridge.
TEST_F(CreaseLines, ALineDrawnAsAQuadIsTheSameLine) {
  TOOND_REQUIRE_SHARED_MODELS();
  const scene::Model windmill = shared_windmill();
  const scene::Model ridge = model_of_obj(turned_obj(ridge_obj(0.5, 8), 30.0));
  for (const scene::Model* model : {&windmill, &ridge}) {
    for (const int msaa : {1, 4}) {
      test::InProcessScene scene({{model, glm::dmat4(1.0)}});
      const RenderParams params = test::complete_params(
          {{"width", 320}, {"height", 320}, {"msaa", msaa}, {"outline", {{"width", 5}, {"creases", "always"}}}});
      RenderParams never = params;
      never.outline.creases = OutlineCreases::Never;
      const RenderOutput bare = scene.render(never);
      const RenderOutput lines = scene.render(params);
      scene.renderer().set_wide_lines(false);
      const RenderOutput quads = scene.render(params);
      ASSERT_NE(lines.plan.find("creases"), std::string::npos) << lines.plan;
      const auto differing = [](const image::Image& a, const image::Image& b) {
        std::size_t values = 0;
        for (std::size_t i = 0; i < a.rgba.size(); ++i) values += std::abs(int(a.rgba[i]) - int(b.rgba[i])) > 2;
        return values;
      };
      const char* what = model == &ridge ? "ridge" : "windmill";
      // Lines were drawn at all (the ridge's one line, five pixels wide,
      // changes a few thousand values; the windmill's, tens of thousands).
      EXPECT_GT(differing(bare.image, lines.image), 1000u) << what << " msaa " << msaa;
      EXPECT_EQ(differing(lines.image, quads.image), 0u) << what << " msaa " << msaa;
    }
  }
}

}  // namespace
}  // namespace toond::render
