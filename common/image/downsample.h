#pragma once
#include "image/image.h"

namespace toond::image {

// Averages each factor × factor block into one pixel: supersampling's
// filter on the CPU (the gallery sheet uses it; the renderer's runs on the GPU, shaders/
// downsample.frag, and its tests hold it to this one). The average is taken
// on linear light, not on the sRGB bytes, so a half-covered edge pixel is
// half as bright, as MSAA's resolve makes it. Colour is weighted by alpha,
// so transparent background does not darken edges. Width and height must be
// multiples of `factor`.
Image downsample_box(const Image& source, int factor);

}  // namespace toond::image
