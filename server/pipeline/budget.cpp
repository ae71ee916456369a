#include "pipeline/budget.h"

#include <algorithm>
#include <string>

#include "limit_error.h"
#include "render/plan/pass_plan.h"
#include "render/plan/pixel_art_frame.h"

namespace toond::pipeline {

using render::SheetLayout;
namespace {

std::string count(double n) { return std::to_string(static_cast<unsigned long long>(n)); }

// A sheet is one answer of many frames: its whole image counts against
// the output pixels, and the samples of all its frames together against
// the sample budget, so a sheet asks no more of the daemon than one render
// may. Its frames are drawn one at a time, each within the per-render
// checks that follow.
// An animation (sheet.animate) holds every frame whole, so its frames'
// pixels count instead of the sheet's (the same but for padding); a
// pixel-art sheet's frames are drawn as `drawn` says. A sheet of several
// layers (sheet.layers) counts as that many sheets, as many as the answers
// that draw them all (pipeline/sheet_layers.h) hold at once.
void check_sheet_budget(const RenderParams& p, const SheetLayout& layout, const RenderParams& drawn,
                        const RenderLimits& limits) {
  const std::size_t layers = std::max<std::size_t>(1, p.sheet->layers.size());
  const std::string in_layers = layers > 1 ? " in " + std::to_string(layers) + " layers" : "";
  const std::string fewer_layers = layers > 1 ? ", fewer sheet.layers" : "";
  const double pixels =
      static_cast<double>(layers) * (p.sheet->animate ? static_cast<double>(layout.frames.size()) * p.width * p.height
                                                      : static_cast<double>(layout.width) * layout.height);
  if (pixels > static_cast<double>(limits.max_output_pixels)) {
    const std::string what = p.sheet->animate ? "the animation of " + std::to_string(layout.frames.size()) + " frames"
                                              : "the sheet of " + std::to_string(layout.columns) + " × " +
                                                    std::to_string(layout.rows) + " tiles";
    throw LimitError(422, "--max-output-pixels",
                     what + in_layers + " is " + count(pixels) + " pixels, more than the limit --max-output-pixels = " +
                         count(static_cast<double>(limits.max_output_pixels)) + "; lower sheet.frames, the pitches" +
                         fewer_layers + ", or width and height",
                     "/sheet/frames");
  }
  const double frames = static_cast<double>(layout.frames.size() * layers);
  const double samples = frames * drawn.width * drawn.supersample * drawn.height * drawn.supersample * drawn.msaa;
  if (samples > static_cast<double>(limits.max_samples)) {
    throw LimitError(
        422, "--max-samples",
        count(frames) + " frames" + in_layers + " × width × height × supersample² × msaa = " + count(samples) +
            " samples, more than the limit --max-samples = " + count(static_cast<double>(limits.max_samples)) +
            "; lower sheet.frames, the pitches" + fewer_layers + ", msaa or supersample",
        "/sheet/frames");
  }
}

// The checks every single render must pass, on the parameters it is
// drawn with.
void check_drawn_render(const RenderParams& p, const RenderLimits& limits) {
  const double pixels = static_cast<double>(p.width) * p.height;
  if (pixels > static_cast<double>(limits.max_output_pixels)) {
    throw LimitError(422, "--max-output-pixels",
                     "width × height = " + count(pixels) + " pixels, more than the limit --max-output-pixels = " +
                         count(static_cast<double>(limits.max_output_pixels)),
                     "/width");
  }
  if (p.lights.size() > limits.max_lights) {
    throw LimitError(422, "--max-lights",
                     std::to_string(p.lights.size()) +
                         " lights, more than the limit --max-lights = " + std::to_string(limits.max_lights),
                     "/lights");
  }
  if (p.objects.size() > limits.max_objects) {
    throw LimitError(422, "--max-objects",
                     std::to_string(p.objects.size()) +
                         " objects, more than the limit --max-objects = " + std::to_string(limits.max_objects),
                     "/objects");
  }
  const double side_w = static_cast<double>(p.width) * p.supersample;
  const double side_h = static_cast<double>(p.height) * p.supersample;
  if (side_w > kMaxDrawnSide || side_h > kMaxDrawnSide) {
    throw LimitError(422, "--max-samples",
                     "width/height × supersample exceeds " + std::to_string(kMaxDrawnSide) +
                         " pixels on a side, the largest framebuffer drawn; lower supersample",
                     "/supersample");
  }
  const double samples = side_w * side_h * p.msaa;
  if (samples > static_cast<double>(limits.max_samples)) {
    throw LimitError(422, "--max-samples",
                     "width × height × supersample² × msaa = " + count(samples) +
                         " samples, more than the limit --max-samples = " +
                         count(static_cast<double>(limits.max_samples)) + "; lower msaa or supersample",
                     p.msaa > 1 ? "/msaa" : "/supersample");
  }
}

}  // namespace

void check_render_budget(const RenderParams& p, const std::optional<SheetLayout>& layout, const RenderLimits& limits) {
  // The framebuffer and sample checks weigh what is drawn, not what was
  // asked: a pixel-art sheet draws each frame at 1/scale, one sample a
  // pixel; a data layer draws one sample a pixel, unsupersampled (the pass
  // plan gives it the Layer pass alone), whatever msaa and supersample say.
  const bool pixel_art = p.sheet && p.sheet->pixel_art;
  RenderParams drawn = pixel_art ? render::pixel_art_frame_params(p, *p.sheet->pixel_art) : p;
  if (render::is_data_layer(p.output)) {
    drawn.msaa = 1;
    drawn.supersample = 1;
  }
  if (layout) check_sheet_budget(p, *layout, drawn, limits);
  check_drawn_render(drawn, limits);
}

}  // namespace toond::pipeline
