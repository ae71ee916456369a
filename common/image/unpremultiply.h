#pragma once
#include "image/image.h"

namespace toond::image {

// Turns colour premultiplied by alpha in linear light (sRGB-encoded bytes
// of c·a) into straight alpha (the bytes of c), as PNG stores it: dividing
// the linear value by alpha, so composited in linear light over any
// background the pixel gives back what was blended into the target.
// Fully transparent pixels become all zero.
void unpremultiply_linear(Image& image);

}  // namespace toond::image
