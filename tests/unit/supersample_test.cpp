// Supersampling shrinks the drawn image on the GPU (downsample.frag). Its
// yardstick is the CPU box filter (image/downsample.h) over the same image
// drawn at the larger size without supersampling: a request at N² with
// supersample k draws exactly what one at (kN)² with every pixel size
// multiplied by k draws.
#include <gtest/gtest.h>

#include <string>

#include "image/downsample.h"
#include "scene/import/bundle_import.h"
#include "scene/import/demo_model.h"
#include "support/gl_context_test.h"
#include "support/golden_compare.h"
#include "support/in_process_render.h"

namespace toond::render {
namespace {

using nlohmann::json;

constexpr int kSize = 40;

// Pixels the drawing covers in part (0 < alpha < 255): where the filter's
// alpha weighting shows.
std::size_t partly_covered(const image::Image& img) {
  std::size_t n = 0;
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) n += img.rgba[i] > 0 && img.rgba[i] < 255;
  return n;
}

class SupersampleOnTheGpu : public test::GlContextTest {
 protected:
  static const scene::Model& demo() {
    static const scene::Model model = scene::import_bundle(scene::make_demo_bundle());
    return model;
  }

  // The request at kSize² with supersample k, and the CPU box filter of the
  // same request drawn at (k·kSize)².
  static void expect_same_as_the_box_filter(json request, int k, const std::string& what) {
    request["width"] = request["height"] = kSize;
    request["supersample"] = k;
    request["lod"] = "full";  // the automatic level depends on the output size
    const image::Image on_gpu = test::render_in_process(demo(), request);
    json larger = request;
    larger["width"] = larger["height"] = kSize * k;
    larger["supersample"] = 1;
    larger["outline"]["width"] = request["outline"]["width"].get<double>() * k;
    const image::Image on_cpu = image::downsample_box(test::render_in_process(demo(), larger), k);
    ASSERT_EQ(on_gpu.width, kSize);
    ASSERT_EQ(on_gpu.height, kSize);
    // Both over a transparent background: edges and lines are partly
    // covered, so a filter that ignored alpha would show.
    EXPECT_GT(partly_covered(on_cpu), 50u) << what << " ×" << k;
    const test::GoldenDiff d = test::compare_golden(on_cpu, on_gpu);
    std::printf("[supersample] %s ×%d: largest difference %d levels\n", what.c_str(), k, d.largest);
    EXPECT_TRUE(d.same_size) << what << " ×" << k;
    EXPECT_LE(d.largest, 1) << what << " ×" << k;
  }
};

// Over a transparent background, so edge pixels average drawn colour with
// transparent samples: the colour must not darken, the alpha must fall.
TEST_F(SupersampleOnTheGpu, EqualsTheBoxFilterOfTheLargerDrawing) {
  const json request = {{"background", {0.2, 0.3, 0.4, 0.0}}, {"outline", {{"width", 1.5}}}};
  for (int k : {2, 3, 4}) expect_same_as_the_box_filter(request, k, "colour");
}

// The lines layer is drawn premultiplied: the GPU divides the block's sums
// by its alpha; the CPU path divides each pixel first, then averages.
TEST_F(SupersampleOnTheGpu, TheLinesLayerEqualsTheBoxFilterOfItsStraightColour) {
  const json request = {{"output", "lines"}, {"outline", {{"width", 1.5}, {"color", {0.9, 0.2, 0.1}}}}};
  for (int k : {2, 3}) expect_same_as_the_box_filter(request, k, "lines");
}

}  // namespace
}  // namespace toond::render
