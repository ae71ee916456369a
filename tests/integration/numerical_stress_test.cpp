// Numerical stability: inputs that break a naive float pipeline. Geometry
// far from the origin or at extreme scales, every band count and rounding,
// grazing lights and views, extreme fields of view, a camera almost inside
// the model, degenerate meshes: each renders a sane image, the same image
// every time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "image/png_codec.h"
#include "support/edge_measure.h"
#include "support/generated_models.h"
#include "support/image_checks.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

constexpr int kStressSize = 256;

class NumericalStress : public SharedDaemonTest {
 public:
  // No result cache: a repeated request must be rendered again, so that two
  // renders of the same input can be compared byte for byte.
  static void SetUpTestSuite() {
    daemon_ = std::make_unique<Daemon>(std::filesystem::path{}, std::vector<std::string>{"--result-cache-mb", "0"});
  }

 protected:
  static std::string upload(const std::string& obj, const std::string& name = "model.obj") {
    auto client = daemon().client();
    return upload_obj_text(client, obj, name);
  }
  static const std::string& unit_sphere() {
    static const std::string id = upload(sphere_obj(64, 32));
    return id;
  }

  // A white, unoutlined, unhighlighted model on a grey background (lighter
  // than the ambient band, and no band's level): every pixel is a grey
  // between the ambient band and white, so anything darker than the
  // ambient level, or coloured, is garbage (NaN shading becomes 0 or an
  // undefined value in the framebuffer).
  static json grey_params(const std::string& model) {
    return {{"model", model},
            {"width", kStressSize},
            {"height", kStressSize},
            {"background", {0.6, 0.6, 0.6}},
            {"ambient", 0.25},
            {"shading", {{"base", "white"}}},
            {"specular", {{"enabled", false}}},
            {"outline", {{"enabled", false}}}};
  }

  // Pixels that cannot come from the grey pipeline above.
  static std::size_t garbage_pixels(const image::Image& img, double ambient, Rgb background = {153, 153, 153}) {
    const int floor_byte =
        static_cast<int>(std::floor(255.0 * std::pow(ambient, 1.0 / 2.4) * 1.055 - 0.055 * 255.0)) - 2;
    std::size_t bad = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const Rgb c = rgb_at(img, x, y);
        if (c == background) continue;
        if (c.r != c.g || c.g != c.b || c.r < floor_byte) ++bad;
      }
    return bad;
  }

  static std::string render_png(const json& params) {
    auto client = daemon().client();
    auto res = post_json(client, "/render", params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << "render failed: " << (res ? res->body : "no answer") << "\n" << params.dump();
      return {};
    }
    return res->body;
  }
};

double fraction_differing(const image::Image& a, const image::Image& b) {
  if (a.width != b.width || a.height != b.height) return 1.0;
  std::size_t differ = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) differ += rgb_at(a, x, y) != rgb_at(b, x, y) ? 1 : 0;
  return static_cast<double>(differ) / (static_cast<double>(a.width) * a.height);
}

// Double-precision import, recentring in double and near/far planes fitted
// to the bounds: the same sphere 1e5 away or at 1e-4 and 1e4 scale frames
// and shades like the unit sphere, with the default look (outline, MSAA,
// default light and camera).
TEST_F(NumericalStress, FarAndTinyAndHugeSpheresRenderLikeTheUnitSphere) {
  auto client = daemon().client();
  const json base = {{"width", kStressSize}, {"height", kStressSize}};
  json params = base;
  params["model"] = unit_sphere();
  const auto reference = render_ok(client, params);
  ASSERT_GT(coverage(foreground_mask(reference)), 0.1);
  const struct {
    const char* name;
    double radius;
    glm::dvec3 centre;
  } cases[] = {{"offset 1e5 in x", 1, {1e5, 0, 0}},
               {"offset 1e5 in y", 1, {0, 1e5, 0}},
               {"offset 1e5 in z", 1, {0, 0, 1e5}},
               {"offset 1e5 in every axis", 1, {1e5, -1e5, 1e5}},
               {"scale 1e-4", 1e-4, {0, 0, 0}},
               {"scale 1e4", 1e4, {0, 0, 0}},
               {"scale 1e-4 offset 1e5", 1e-4, {1e5, 1e5, 1e5}}};
  for (const auto& c : cases) {
    params["model"] = upload(sphere_obj(64, 32, c.radius, c.centre));
    const auto img = render_ok(client, params);
    const double differ = fraction_differing(reference, img);
    std::printf("[stress] %s: %.4f %% of pixels differ from the unit sphere\n", c.name, differ * 100.0);
    EXPECT_LE(differ, 0.005) << c.name;
  }
}

// Light from the side: N·L = x/R across the disk, so every band is a stripe
// of the same width and each one shows, even at 64 steps. Ceil and round
// show the shadow band as well as `steps` lit ones; floor's top band is only
// the single point facing the light.
TEST_F(NumericalStress, BandCountEqualsStepsForEveryRounding) {
  auto client = daemon().client();
  json params = grey_params(unit_sphere());
  params["width"] = 512;
  params["height"] = 512;
  params["msaa"] = 1;
  // Not white: the top band of a white model is white.
  params["background"] = {1, 0, 0};
  params["camera"] = {{"projection", "orthographic"}, {"yaw", 0}, {"pitch", 0}};
  params["lights"] = {{{"type", "directional"}, {"direction", {-1, 0, 0}}}};
  for (const std::string rounding : {"ceil", "floor", "round"}) {
    for (int steps : {1, 2, 5, 16, 64}) {
      params["shading"] = {{"base", "white"}, {"steps", steps}, {"rounding", rounding}, {"band_aa", false}};
      const auto img = render_ok(client, params);
      const auto hist = colour_histogram(img, foreground_mask(img));
      std::size_t bands = 0;
      for (const auto& [colour, n] : hist) bands += n >= 8 ? 1 : 0;
      const std::size_t expected = static_cast<std::size_t>(steps) + (rounding == "floor" ? 0 : 1);
      EXPECT_EQ(bands, expected) << rounding << " " << steps << " steps";
      EXPECT_EQ(garbage_pixels(img, 0.25, {255, 0, 0}), 0u) << rounding << " " << steps << " steps";
    }
  }
}

// Grazing lights and views, extreme fields of view and a camera almost
// touching the surface: every pixel is background or a legal band colour,
// the model shows, and the same request gives the same bytes.
TEST_F(NumericalStress, ExtremeViewsAndLightsGiveSaneRepeatableImages) {
  struct Case {
    const char* name;
    json camera;
    json light_direction;
  };
  const Case cases[] = {
      {"grazing light", {{"yaw", 0}, {"pitch", 0}}, {-1, 0, -1e-6}},
      {"light along the view", {{"yaw", 0}, {"pitch", 0}}, {0, 0, -1}},
      {"light from behind", {{"yaw", 0}, {"pitch", 0}}, {0, 0, 1}},
      {"grazing view from above", {{"yaw", 0}, {"pitch", 89}}, {0, -1, -1}},
      {"grazing view from below", {{"yaw", 360}, {"pitch", -89}}, {0, 1, -1}},
      {"fov 1", {{"fov", 1}}, {-0.4, -0.5, -1}},
      {"fov 170", {{"fov", 170}}, {-0.4, -0.5, -1}},
      {"camera a hair outside the surface", {{"yaw", 0}, {"pitch", 0}, {"distance", 1.0005}}, {0, 0, -1}},
      {"camera inside the bounds, orthographic",
       {{"projection", "orthographic"}, {"yaw", 0}, {"pitch", 0}, {"distance", 1.2}},
       {0, 0, -1}},
      {"tiny light vector", {{"yaw", 0}, {"pitch", 0}}, {1e-30, 0, -1e-30}},
  };
  for (const Case& c : cases) {
    json params = grey_params(unit_sphere());
    params["camera"] = c.camera;
    params["lights"] = {{{"type", "directional"}, {"direction", c.light_direction}}};
    params["shading"]["steps"] = 4;
    const std::string first = render_png(params);
    const std::string second = render_png(params);
    ASSERT_FALSE(first.empty()) << c.name;
    EXPECT_EQ(first, second) << c.name << ": two renders of the same request differ";
    const auto img = image::decode_png(first);
    // Not the corner-pixel mask: close up, the model fills the corners.
    std::size_t model_pixels = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) model_pixels += rgb_at(img, x, y) != Rgb{153, 153, 153} ? 1 : 0;
    EXPECT_GT(model_pixels, 30u) << c.name;
    EXPECT_EQ(garbage_pixels(img, 0.25), 0u) << c.name;
  }
}

// A convex model with shadows on shades exactly as without them wherever it
// faces the light: no acne, from the front or at an angle, for small and
// large maps.
TEST_F(NumericalStress, NoSelfShadowOnTheLitSideOfAConvexModel) {
  auto client = daemon().client();
  for (const json& direction : {json{0, 0, -1}, json{-0.5, -0.4, -1}, json{-1, -0.2, -0.3}}) {
    json params = grey_params(unit_sphere());
    params["camera"] = {{"yaw", 0}, {"pitch", 0}};
    params["lights"] = {{{"type", "directional"}, {"direction", direction}}};
    params["shading"]["steps"] = 4;
    const auto without = render_ok(client, params);
    const LinearChannel plain(without, 1);
    for (int map_size : {512, 4096}) {
      params["shadows"] = {{"enabled", true}, {"map_size", map_size}};
      const auto with = render_ok(client, params);
      const LinearChannel shadowed(with, 1);
      // The lit half: above the first band, so clear of the terminator
      // where the shadow map and N·L both say "dark" anyway.
      std::size_t darkened = 0, lit = 0;
      for (int y = 0; y < kStressSize; ++y)
        for (int x = 0; x < kStressSize; ++x) {
          if (plain.at(x, y) < 0.25 + 0.75 * 0.5 || plain.at(x, y) > 0.999) continue;
          ++lit;
          darkened += shadowed.at(x, y) < plain.at(x, y) - 1e-3 ? 1 : 0;
        }
      EXPECT_GT(lit, 1000u);
      EXPECT_EQ(darkened, 0u) << "light " << direction.dump() << " map " << map_size;
    }
  }
}

// A cube standing on the floor, lit at 45° from the upper right: its shadow
// starts at its left side, where it touches the floor, and runs a cube's
// width to the left. No lit strip between the cube and its shadow (shadows
// lifted off their casters, "peter-panning"), and no shadow cut short where
// the floor lies past the model's bounds as the light sees them.
TEST_F(NumericalStress, ShadowTouchesItsCasterAtTheContact) {
  auto client = daemon().client();
  json params = grey_params(upload(cube_obj(1.0), "cube.obj"));
  params["msaa"] = 1;
  params["width"] = 384;
  params["height"] = 384;
  params["camera"] = {{"projection", "orthographic"}, {"yaw", 0}, {"pitch", 20}};
  params["lights"] = {{{"type", "directional"}, {"direction", {-1, -1, 0}}}};
  params["shading"]["band_aa"] = false;
  const auto cube_only = render_ok(client, params);
  params["floor"] = {{"enabled", true}, {"size", 3}, {"color", {0.8, 0.8, 0.8}}};
  const auto lit = render_ok(client, params);
  for (int map_size : {512, 2048}) {
    params["shadows"] = {{"enabled", true}, {"map_size", map_size}};
    const auto shadowed = render_ok(client, params);
    const int w = shadowed.width;
    auto darkened = [&](int x, int y) {
      return x >= 0 && luminance(rgb_at(shadowed, x, y)) < luminance(rgb_at(lit, x, y)) - 0.05;
    };
    std::size_t rows = 0, gaps = 0, short_rows = 0;
    for (int y = 0; y < shadowed.height; ++y) {
      int left = 0;
      while (left < w && rgb_at(cube_only, left, y) == Rgb{153, 153, 153}) ++left;
      if (left == w) continue;
      int right = left;
      while (right < w && rgb_at(cube_only, right, y) != Rgb{153, 153, 153}) ++right;
      bool shadow_near = false;
      for (int x = left - 10; x < left - 2; ++x) shadow_near = shadow_near || darkened(x, y);
      if (!shadow_near) continue;
      ++rows;
      gaps += darkened(left - 2, y) ? 0 : 1;
      bool full_length = true;
      for (int x = std::max(0, left - (right - left) * 9 / 10); x < left - 2; ++x)
        full_length = full_length && darkened(x, y);
      short_rows += full_length ? 0 : 1;
    }
    EXPECT_GT(rows, 20u) << "map " << map_size << ": the shadow reaches the cube on that many rows";
    EXPECT_EQ(gaps, 0u) << "map " << map_size << ": rows with more than a pixel of lit floor before the shadow";
    EXPECT_EQ(short_rows, 0u) << "map " << map_size << ": rows where the shadow stops short of a cube's width";
  }
}

// Meshes that break naive code: zero-area triangles, zero-length and
// flipped normals, duplicated vertices, a big index count. Each uploads
// and renders something sane.
TEST_F(NumericalStress, DegenerateMeshesRenderSanely) {
  std::string degenerate = sphere_obj(24, 12);
  // Zero-area triangles: a repeated corner, three collinear points.
  degenerate += "v 0 0 0\nv 0.5 0 0\nv 1 0 0\n";
  degenerate += "f 1 1 2\nf -1 -2 -3\n";
  // Zero-length and flipped normals on a quad in front of the sphere.
  std::string normals = sphere_obj(24, 12);
  normals += "v -0.5 -0.5 1.5\nv 0.5 -0.5 1.5\nv 0.5 0.5 1.5\nv -0.5 0.5 1.5\nvn 0 0 0\nvn 0 0 -1\n";
  normals += "f -4//-2 -3//-2 -2//-1\nf -4//-1 -2//-2 -1//-2\n";
  // Every vertex written twice, faces using either copy.
  std::string duplicated = "# duplicated vertices\n";
  {
    const std::string sphere = sphere_obj(16, 8);
    std::size_t pos = 0;
    while (pos < sphere.size()) {
      const std::size_t end = sphere.find('\n', pos);
      const std::string line = sphere.substr(pos, end - pos);
      pos = end + 1;
      if (line.rfind("v ", 0) == 0)
        duplicated += line + "\n" + line + "\n";
      else if (line.rfind("vn ", 0) == 0)
        duplicated += line + "\n" + line + "\n";
      else if (line.rfind("f ", 0) == 0) {
        // Vertex i (1-based) is now 2i-1 and 2i; normals likewise.
        std::string face = "f";
        std::size_t p = 2;
        int corner = 0;
        while (p < line.size()) {
          const std::size_t space = line.find(' ', p);
          const std::string ref = line.substr(p, space == std::string::npos ? std::string::npos : space - p);
          const int v = std::stoi(ref.substr(0, ref.find('/')));
          const int copy = 2 * v - (corner++ % 2);
          face += " " + std::to_string(copy) + "//" + std::to_string(copy);
          if (space == std::string::npos) break;
          p = space + 1;
        }
        duplicated += face + "\n";
      }
    }
  }
  // 65k triangles, 196k indices: past every 16-bit limit.
  const std::string dense = sphere_obj(256, 128);

  auto client = daemon().client();
  for (const auto& [name, obj] : std::map<std::string, std::string>{{"degenerate triangles", degenerate},
                                                                    {"bad normals", normals},
                                                                    {"duplicated vertices", duplicated},
                                                                    {"dense", dense}}) {
    const std::string id = upload(obj, "stress.obj");
    ASSERT_FALSE(id.empty()) << name;
    json params = grey_params(id);
    params["lights"] = {{{"type", "directional"}, {"direction", {0, 0, -1}}}};
    params["camera"] = {{"yaw", 0}, {"pitch", 0}};
    const auto img = render_ok(client, params);
    EXPECT_GT(coverage(foreground_mask(img)), 0.05) << name;
    EXPECT_EQ(garbage_pixels(img, 0.25), 0u) << name;
  }
  auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

}  // namespace
}  // namespace toond::test
