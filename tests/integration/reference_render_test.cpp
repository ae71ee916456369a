// Scenes without an analytic answer are measured against the same pipeline
// at its highest quality (supersample 4 × MSAA 8, a 4096² shadow map): each
// step up the quality ladder must bring the image closer to that reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "support/edge_measure.h"
#include "support/generated_models.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

struct ImageError {
  double mean_abs = 0;     // linear light, mean over pixels and RGB
  double percent_off = 0;  // pixels with a channel more than 8/255 (sRGB) off
};

ImageError image_error(const image::Image& img, const image::Image& ref) {
  ImageError e;
  if (img.width != ref.width || img.height != ref.height) return {1.0, 100.0};
  std::size_t off = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      bool pixel_off = false;
      for (int c = 0; c < 3; ++c) {
        const int a = img.pixel(x, y)[c], b = ref.pixel(x, y)[c];
        e.mean_abs += std::abs(srgb_byte_to_linear(a) - srgb_byte_to_linear(b));
        pixel_off = pixel_off || std::abs(a - b) > 8;
      }
      off += pixel_off ? 1 : 0;
    }
  const double pixels = static_cast<double>(img.width) * img.height;
  e.mean_abs /= pixels * 3;
  e.percent_off = 100.0 * static_cast<double>(off) / pixels;
  return e;
}

class ReferenceRender : public SharedDaemonTest {
 protected:
  // Renders `scene` along the quality ladder and against the reference;
  // each rung must be closer than the one below it.
  static void check_ladder(const char* name, json scene) {
    auto client = daemon().client();
    // Small: the reference draws 16× the pixels at 8 samples each.
    scene["width"] = 160;
    scene["height"] = 160;
    json reference = scene;
    reference["supersample"] = 4;
    reference["msaa"] = 8;
    if (scene.contains("shadows")) reference["shadows"]["map_size"] = 4096;
    const auto ref = render_ok(client, reference);
    const struct {
      const char* label;
      int msaa, supersample, map;
    } ladder[] = {{"msaa 1, map 1024", 1, 1, 1024},
                  {"msaa 4, map 2048 (default)", 4, 1, 2048},
                  {"supersample 2 × msaa 4, map 4096", 4, 2, 4096}};
    double previous = 1e9;
    for (const auto& rung : ladder) {
      json params = scene;
      params["msaa"] = rung.msaa;
      params["supersample"] = rung.supersample;
      if (scene.contains("shadows")) params["shadows"]["map_size"] = rung.map;
      const ImageError e = image_error(render_ok(client, params), ref);
      std::printf("[reference] %s, %s: mean abs error %.5f, %.2f %% of pixels off\n", name, rung.label, e.mean_abs,
                  e.percent_off);
      EXPECT_LT(e.mean_abs, previous) << name << ": " << rung.label;
      previous = e.mean_abs;
    }
  }
};

TEST_F(ReferenceRender, SphereOnAShadowedFloorConvergesToTheReference) {
  auto client = daemon().client();
  const std::string id = upload_obj_text(client, sphere_obj(96, 48), "sphere.obj");
  check_ladder("sphere on a floor with shadows",
               {{"model", id},
                {"camera", {{"yaw", 20}, {"pitch", 30}}},
                {"lights", {{{"type", "directional"}, {"direction", {0.5, -1, -0.3}}}}},
                {"floor", {{"enabled", true}, {"size", 2}}},
                {"shadows", {{"enabled", true}}}});
}

TEST_F(ReferenceRender, SpotConvergesToTheReference) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  for (const char* folder : {"spot"}) {
    auto res = upload_model_folder(client, shared_models_dir() / folder);
    ASSERT_TRUE(res && (res->status == 200 || res->status == 201)) << folder;
    check_ladder(folder, {{"model", json::parse(res->body)["id"]}, {"camera", {{"yaw", -140}, {"pitch", 12}}}});
  }
}

}  // namespace
}  // namespace toond::test
