#pragma once
// Nearest-neighbour enlargement by a whole factor: every source pixel
// becomes a factor×factor block of itself, no new colour in between (what
// pixel art needs; any filter would blur the palette away).
#include "image/image.h"

namespace toond::image {

// Writes `source` enlarged `factor` times into `target` with its top-left
// corner at (x, y); the enlarged image must lie inside `target`.
void blit_upscaled(const Image& source, int factor, Image& target, int x, int y);

}  // namespace toond::image
