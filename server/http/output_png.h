#pragma once
// The answer's PNG for each `output`: the color render and the lines layer
// as they were read back, the data layers (depth, normal, id) through
// image/layer_png with what they mean in tEXt chunks (and a depth's range
// in a header too).
#include <string>
#include <utility>
#include <vector>

#include "image/png_codec.h"
#include "render/render_service.h"

namespace toond::http {

struct OutputPng {
  std::string png;
  std::vector<std::pair<std::string, std::string>> headers;  // beside the answer's usual ones
};

// Before rendering: an id layer numbers at most 255 objects or materials
// (one palette index each); more is a 422 naming `output`.
void check_output_fits(const render::RenderJob& job);

// `options.text` (a sheet's atlas) is kept; the layer's own chunks follow.
OutputPng encode_output(const render::RenderOutput& out, const render::RenderJob& job,
                        const image::PngOptions& options);

}  // namespace toond::http
