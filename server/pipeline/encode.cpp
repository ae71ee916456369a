#include "pipeline/encode.h"

#include <algorithm>
#include <cmath>

#include "image/png_codec.h"
#include "image/webp_animation.h"
#include "pipeline/output_png.h"
#include "pipeline/sheet_answer.h"

namespace toond::pipeline {
namespace {

// An animated sheet's frames show as long as the clip's own: whole
// milliseconds that add up as the exact times do (83, 84, 83 ms for 1/12 s),
// so a long loop does not drift. A turntable's show `frame_ms` each. The
// frames play in the atlas's order, each direction's row once; that
// sequence loops forever, but a sheet of one-shot clips alone plays it once
// and stays on its last pose, as the clips do.
image::WebpAnimationOptions animation_options(const Request& request) {
  const render::SheetParams& sheet = *request.params.sheet;
  image::WebpAnimationOptions animation;
  animation.frame_ms = sheet.frame_ms;
  if (sheet.clips.empty()) return animation;
  const bool one_shots =
      std::none_of(sheet.clips.begin(), sheet.clips.end(), [](const render::SheetClip& clip) { return clip.loop; });
  animation.loop_count = one_shots ? 1 : 0;
  double elapsed = 0;
  for (const render::SheetFrame& frame : request.layout->frames) {
    const double next = elapsed + frame.duration_ms;
    animation.durations_ms.push_back(
        std::max(1, static_cast<int>(std::lround(next)) - static_cast<int>(std::lround(elapsed))));
    elapsed = next;
  }
  return animation;
}

}  // namespace

Encoded encode(const render::RenderOutput& out, const Request& request,
               const std::optional<nlohmann::ordered_json>& atlas) {
  if (request.answer.file != SheetFile::Image) return encode_sheet_file(&out, request, *atlas);
  Encoded encoded;
  if (request.params.sheet && request.params.sheet->animate) {
    encoded.body = image::encode_webp_animation(out.frames, animation_options(request));
    encoded.content_type = "image/webp";
    encoded.stage = "webp";
    return encoded;
  }
  image::PngOptions png_options;
  png_options.compression_level = request.params.png_compression;
  if (atlas) png_options.text.emplace_back("toond:atlas", atlas->dump());
  OutputPng png = encode_output(out, request.output, png_options);
  encoded.body = std::move(png.png);
  encoded.headers = std::move(png.headers);
  return encoded;
}

}  // namespace toond::pipeline
