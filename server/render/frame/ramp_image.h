#pragma once
// A lighting ramp drawn as an image (a "sharp lighting map": e.g. 16
// texels holding 3 shades) turned into ramp stops, so an image
// ramp and a JSON ramp share one shader path and one meaning.
#include <stdexcept>
#include <vector>

#include "render/plan/render_params.h"
#include "scene/mesh/model.h"

namespace toond::render {

// More runs of equal texels than the shader's ramp holds (a smooth gradient
// is not a cel ramp); the message says how many.
struct RampImageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int max_ramp_bands = 16;

// Reads the image's middle row left to right. Texel i of W covers N·L in
// [i/W, (i+1)/W); each run of equal texels becomes one stop whose colour is
// the texel decoded from sRGB. The first stop starts at N·L = -1, so surfaces
// facing away from the light take texel 0, the shadow band. Alpha is ignored.
std::vector<RampStop> ramp_from_image(const scene::Texture& image);

}  // namespace toond::render
