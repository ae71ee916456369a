// Golden images: every preset, and each feature the presets leave out,
// rendered in process on the test's GL context from the request a user
// would send (preset expanded, schema defaults filled in), compared with a
// stored reference. They guard refactors of the renderer: a change that
// moves pixels shows up here with a diff image.
//
// References live in tests/golden/<case>.png for Mesa's CPU rasterizers
// (what CI runs) and in tests/golden/<vendor>/ for a GPU driver: two
// rasterizers differ in many edge pixels by more than the tolerance (their
// sample patterns, alpha-to-coverage dithering and float rounding at hard
// band thresholds), so a reference holds only where it was made. A driver
// without a set is skipped, saying so. TOOND_BLESS=1 rewrites the set of the
// context's driver; a commit that changes a reference says why.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "image/png_codec.h"
#include "model_checks.h"
#include "presets.h"
#include "scene/import/bundle_import.h"
#include "scene/import/demo_model.h"
#include "support/generated_models.h"
#include "support/gl_context_test.h"
#include "support/golden_compare.h"
#include "support/in_process_render.h"

namespace toond::render {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kSize = 96;

enum class Subject { Demo, Sphere, Cube, SphereAndCube, ColouredCube };

struct GoldenCase {
  std::string name;
  Subject subject;
  json request;
};

// Every preset on the demo model (textured sphere on a hard-edged box).
std::vector<GoldenCase> preset_cases() {
  std::vector<GoldenCase> cases;
  for (const auto& [name, preset] : proto::Presets::builtin().document().items()) {
    cases.push_back({"preset_" + name, Subject::Demo, {{"preset", name}}});
  }
  return cases;
}

// What the presets leave out, one feature a case.
std::vector<GoldenCase> feature_cases() {
  const json point = {{"type", "point"}, {"position", {0.8, 1.2, 1.5}}, {"radius", 4}};
  return {
      {"default_demo", Subject::Demo, json::object()},
      {"default_sphere", Subject::Sphere, json::object()},
      {"msaa_1", Subject::Demo, {{"msaa", 1}}},
      {"supersample_2", Subject::Demo, {{"supersample", 2}}},
      {"orthographic", Subject::Demo, {{"camera", {{"projection", "orthographic"}, {"yaw", -20}, {"pitch", 30}}}}},
      {"phong", Subject::Sphere, {{"shading", {{"mode", "phong"}}}}},
      {"flat", Subject::Sphere, {{"shading", {{"mode", "flat"}}}}},
      {"steps_6_floor", Subject::Sphere, {{"shading", {{"steps", 6}, {"rounding", "floor"}}}}},
      {"steps_4_round", Subject::Sphere, {{"shading", {{"steps", 4}, {"rounding", "round"}}}}},
      {"band_aa_off", Subject::Sphere, {{"shading", {{"band_aa", false}}}}},
      {"two_tone", Subject::Sphere, {{"shading", {{"two_tone", {{"enabled", true}}}}}}},
      {"ramp_colors",
       Subject::Sphere,
       {{"shading", {{"ramp", {{{"at", 0}, {"color", {0.2, 0.1, 0.4}}}, {{"at", 0.5}, {"color", {0.9, 0.6, 0.3}}}}}}}}},
      {"base_white", Subject::Demo, {{"shading", {{"base", "white"}}}}},
      {"specular_off", Subject::Sphere, {{"specular", {{"enabled", false}}}}},
      {"specular_broad", Subject::Sphere, {{"specular", {{"shininess", 8}, {"threshold", 0.3}}}}},
      {"rim_default", Subject::Sphere, {{"rim", {{"enabled", true}}}}},
      {"rim_lit", Subject::Sphere, {{"rim", {{"enabled", true}, {"mask", "lit"}, {"color", {1, 0.3, 0.2}}}}}},
      {"rim_both_smooth", Subject::Sphere, {{"rim", {{"enabled", true}, {"mask", "both"}, {"threshold", 0}}}}},
      {"halftone_dots", Subject::Sphere, {{"halftone", {{"enabled", true}, {"style", "dots"}}}}},
      {"halftone_checker", Subject::Sphere, {{"halftone", {{"enabled", true}, {"style", "checker"}}}}},
      {"contour_even", Subject::Sphere, {{"contour", {{"enabled", true}, {"style", "even"}}}}},
      {"contour_fresnel", Subject::Sphere, {{"contour", {{"enabled", true}, {"style", "fresnel"}}}}},
      {"outline_off", Subject::Demo, {{"outline", {{"enabled", false}}}}},
      {"outline_wide", Subject::Cube, {{"outline", {{"width", 6}}}}},
      {"outline_world", Subject::Sphere, {{"outline", {{"units", "world"}, {"width", 0.05}}}}},
      {"outline_wireframe", Subject::Cube, {{"outline", {{"method", "wireframe"}, {"width", 3}}}}},
      {"outline_edges", Subject::Cube, {{"outline", {{"method", "edges"}, {"width", 3}}}}},
      {"outline_all_methods", Subject::Cube, {{"outline", {{"method", {"hull", "wireframe", "edges"}}}}}},
      {"outline_creases_never", Subject::Cube, {{"outline", {{"creases", "never"}}}}},
      {"outline_creases_always", Subject::Sphere, {{"outline", {{"creases", "always"}}}}},
      {"outline_material", Subject::Demo, {{"outline", {{"color_mode", "material"}, {"width", 4}}}}},
      {"outline_texture", Subject::Demo, {{"outline", {{"color_mode", "texture"}, {"width", 4}}}}},
      {"shadows_floor", Subject::Demo, {{"shadows", {{"enabled", true}}}, {"floor", {{"enabled", true}}}}},
      {"floor_only", Subject::Sphere, {{"floor", {{"enabled", true}, {"color", {0.5, 0.7, 0.5}}}}}},
      {"point_light", Subject::Sphere, {{"lights", {point}}}},
      {"lights_sum",
       Subject::Sphere,
       {{"light_combine", "sum"},
        {"lights",
         {{{"type", "directional"}, {"direction", {-1, -0.2, -0.5}}, {"color", {1, 0.6, 0.4}}},
          {{"type", "directional"}, {"direction", {1, -0.3, -0.6}}, {"color", {0.3, 0.5, 1}}}}}}},
      {"no_lights", Subject::Sphere, {{"lights", json::array()}}},
      {"background_alpha", Subject::Sphere, {{"background", {0.2, 0.3, 0.4, 0.0}}}},
      {"scene_two_objects", Subject::SphereAndCube, json::object()},
      {"vertex_colors", Subject::ColouredCube, json::object()},
      // A low light from the side throws the sphere's shadow across the
      // floor in view, so a broken shadow pass changes many pixels.
      {"shadows_side_light",
       Subject::Sphere,
       {{"shadows", {{"enabled", true}}},
        {"floor", {{"enabled", true}}},
        {"camera", {{"pitch", 35}, {"zoom", 0.55}}},
        {"lights", {{{"type", "directional"}, {"direction", {1, -0.6, -0.2}}}}}}},
  };
}

// The folder of references for the context's driver: the top folder for
// the CPU rasterizers, else a folder named by the vendor's first word.
fs::path reference_set(const gpu::GlInfo& gl) {
  const fs::path top(TOOND_GOLDEN_DIR);
  if (gpu::software_rasterizer(gl.renderer)) return top;
  std::string vendor = gl.vendor.substr(0, gl.vendor.find(' '));
  for (char& ch : vendor) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return top / vendor;
}

bool blessing() { return std::getenv("TOOND_BLESS") != nullptr; }

class GoldenImage : public test::GlContextTest {
 protected:
  void SetUp() override { set_ = reference_set(context().info()); }

  // Why this driver's references cannot be checked: empty when they can.
  std::string missing_references() const {
    // The CPU rasterizers' set is the one CI checks: missing, it fails.
    if (blessing() || fs::is_directory(set_) || gpu::software_rasterizer(context().info().renderer)) return {};
    return "no golden references for " + context().info().renderer + " (" + context().info().vendor +
           "): they would be in " + set_.string() + "; TOOND_BLESS=1 writes them";
  }

  fs::path set_;

  static const scene::Model& model(Subject subject) {
    static const scene::Model demo = scene::import_bundle(scene::make_demo_bundle());
    static const scene::Model sphere =
        scene::import_bundle(scene::test_checks::make_bundle({{"m.obj", test::sphere_obj(64, 32)}}));
    static const scene::Model cube =
        scene::import_bundle(scene::test_checks::make_bundle({{"m.obj", test::cube_obj()}}));
    // Every corner its own colour (OBJ "v x y z r g b"), faces blending them.
    static const scene::Model coloured = scene::import_bundle(
        scene::test_checks::make_bundle({{"m.obj",
                                          "v -1 -1 -1 1 0 0\nv 1 -1 -1 0 1 0\nv -1 1 -1 0 0 1\nv 1 1 -1 1 1 0\n"
                                          "v -1 -1 1 1 0 1\nv 1 -1 1 0 1 1\nv -1 1 1 1 1 1\nv 1 1 1 0.2 0.2 0.2\n"
                                          "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"}}));
    switch (subject) {
      case Subject::Demo:
        return demo;
      case Subject::ColouredCube:
        return coloured;
      case Subject::Cube:
        return cube;
      case Subject::Sphere:
      case Subject::SphereAndCube:
        break;
    }
    return sphere;
  }

  static image::Image render(const GoldenCase& c) {
    json request = c.request;
    request["width"] = kSize;
    request["height"] = kSize;
    if (c.subject != Subject::SphereAndCube) return test::render_in_process(model(c.subject), request);
    const glm::dmat4 left = glm::translate(glm::dmat4(1.0), glm::dvec3(-1.2, 0.0, 0.0));
    const glm::dmat4 right = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(1.2, 0.0, 0.0)), glm::dvec3(0.7));
    return test::render_in_process({{&model(Subject::Sphere), left}, {&model(Subject::Cube), right}}, request);
  }
};

void check_against_reference(const fs::path& set, const GoldenCase& c, const image::Image& actual) {
  const fs::path reference = set / (c.name + ".png");
  if (blessing()) {
    fs::create_directories(set);
    std::ofstream(reference, std::ios::binary) << image::encode_png(actual);
    return;
  }
  ASSERT_TRUE(fs::exists(reference)) << reference << " is missing: TOOND_BLESS=1 writes it";
  std::ifstream in(reference, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const test::GoldenDiff diff = test::compare_golden(image::decode_png(bytes), actual);
  if (diff.passes()) return;
  const fs::path out = fs::path(TOOND_GOLDEN_DIFF_DIR) / (c.name + ".diff.png");
  fs::create_directories(out.parent_path());
  std::ofstream(out, std::ios::binary) << image::encode_png(test::side_by_side_diff(image::decode_png(bytes), actual));
  ADD_FAILURE() << c.name << ": " << diff.pixels_over << " pixels differ by more than " << test::kGoldenLevels
                << " levels (at most " << test::kGoldenPixels << " may); largest difference " << diff.largest
                << ". Reference | render | difference ×8: " << out;
}

TEST_F(GoldenImage, EveryPresetMatchesItsReference) {
  if (const std::string why = missing_references(); !why.empty()) GTEST_SKIP() << why;
  for (const GoldenCase& c : preset_cases()) {
    SCOPED_TRACE(c.name);
    check_against_reference(set_, c, render(c));
  }
}

TEST_F(GoldenImage, EveryFeatureMatchesItsReference) {
  if (const std::string why = missing_references(); !why.empty()) GTEST_SKIP() << why;
  for (const GoldenCase& c : feature_cases()) {
    SCOPED_TRACE(c.name);
    check_against_reference(set_, c, render(c));
  }
}

TEST(GoldenReferenceSet, CpuRasterizersUseTheTopFolderAndDriversTheirVendorsFolder) {
  const fs::path top(TOOND_GOLDEN_DIR);
  auto gl = [](std::string vendor, std::string renderer) {
    gpu::GlInfo info;
    info.vendor = std::move(vendor);
    info.renderer = std::move(renderer);
    return info;
  };
  EXPECT_EQ(reference_set(gl("Mesa", "llvmpipe (LLVM 15.0.6, 256 bits)")), top);
  EXPECT_EQ(reference_set(gl("NVIDIA Corporation", "NVIDIA H100 80GB HBM3/PCIe/SSE2")), top / "nvidia");
  EXPECT_EQ(reference_set(gl("AMD", "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6)")), top / "amd");
}

// The same request twice gives the same bytes: a reference can be trusted.
TEST_F(GoldenImage, RendersAreRepeatable) {
  const GoldenCase c{"repeat", Subject::Demo, {{"shadows", {{"enabled", true}}}, {"floor", {{"enabled", true}}}}};
  EXPECT_EQ(render(c).rgba, render(c).rgba);
}

}  // namespace
}  // namespace toond::render
