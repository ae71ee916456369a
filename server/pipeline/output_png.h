#pragma once
// The answer's PNG for each `output`: the color render and the lines layer
// as they were read back, the data layers (depth, normal, id) through
// image/layer_png with what they mean in tEXt chunks (and a depth's range
// in a header too).
#include <string>
#include <utility>
#include <vector>

#include "image/png_codec.h"
#include "render/run/render_service.h"

namespace toond::pipeline {

// What encoding a render's image needs besides its pixels, worked out from
// the request before it is queued: the kind of output, and for an id layer
// how many ids there are and what each stands for.
struct OutputDescription {
  render::Output output = render::Output::Color;
  int id_count = 0;
  std::string id_mapping;  // JSON, for the tEXt chunk toond:ids
};

// Throws a 422 naming `output` when an id layer would number more than 255
// objects or materials (one palette index each).
OutputDescription describe_output(const render::RenderParams& params, const std::vector<render::JobObject>& objects);

struct OutputPng {
  std::string png;
  std::vector<std::pair<std::string, std::string>> headers;  // beside the answer's usual ones
};

// `options.text` (a sheet's atlas) is kept; the layer's own chunks follow.
OutputPng encode_output(const render::RenderOutput& out, const OutputDescription& output,
                        const image::PngOptions& options);

}  // namespace toond::pipeline
