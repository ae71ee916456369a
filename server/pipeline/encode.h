#pragma once
// The answer's bytes for an assembled render: a PNG (the colour image or
// the lines layer as drawn, a data layer through output_png.h; a sheet's
// atlas in a tEXt chunk), or for `sheet.animate` an animated WebP, each
// frame shown as long as its time in the clip.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/request.h"
#include "pipeline/streamed_body.h"
#include "render/frame/render_output.h"

namespace toond::pipeline {

struct Encoded {
  std::string body;
  std::string content_type = "image/png";
  // Beside the answer's usual ones (a depth layer's range).
  std::vector<std::pair<std::string, std::string>> headers;
  std::string stage = "png";  // its Server-Timing entry: "png" or "webp"
  // Set: the body is written as it goes out (streamed_body.h), `body` empty.
  std::shared_ptr<const StreamedBody> stream{};
};

// `atlas`: a sheet's (atlas.h), written into its PNG; an animation's goes
// out with ?atlas=json alone. A sheet asked for as a file (?atlas=…) is
// that file (sheet_answer.h).
Encoded encode(const render::RenderOutput& out, const Request& request,
               const std::optional<nlohmann::ordered_json>& atlas);

}  // namespace toond::pipeline
