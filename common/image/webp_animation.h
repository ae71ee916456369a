#pragma once
// Frames of equal size as one animated, lossless WebP (libwebpmux's
// WebPAnimEncoder): what a sprite sheet answers with `sheet.animate`, a
// turntable any browser plays.
#include <span>
#include <string>
#include <vector>

#include "image/image.h"

namespace toond::image {

struct WebpAnimationOptions {
  int frame_ms = 100;  // how long each frame shows
  // Per frame, how long it shows (an animated sheet's clip frames);
  // empty: frame_ms each. Must then have one entry per frame.
  std::vector<int> durations_ms;
  // How many times the whole animation plays; 0: forever.
  int loop_count = 0;
  // libwebp's lossless effort, 0 (fastest) to 9 (smallest); every level
  // decodes to the same pixels. 0: a 24-frame 512² turntable of the demo
  // model encodes in 64 ms to 394 KB, against 317 ms and 342 KB at 1 (one
  // llvmpipe laptop core); a preview wants the answer more than 15 %.
  int effort = 0;
};

// The frames in order, played loop_count times (0: forever) on a
// transparent canvas the size of the first frame. Lossless and with RGB kept under alpha 0 (WebPConfig's
// `exact`), so decoding gives back every frame's RGBA bytes. libwebp merges
// a frame identical to the one before into it (shown for both durations),
// so the animation may hold fewer frames than given, never a different
// timing. Throws std::runtime_error with libwebp's message on failure, or
// std::invalid_argument for no frames or frames of different sizes.
std::string encode_webp_animation(std::span<const Image> frames, const WebpAnimationOptions& options = {});

}  // namespace toond::image
