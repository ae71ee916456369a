#pragma once
// An animated WebP read back with libwebp's own demuxing decoder
// (WebPAnimDecoder), not with anything of toond's: what the tests compare
// `sheet.animate` answers against.
#include <string>
#include <vector>

#include "image/image.h"

namespace toond::test {

struct WebpFrames {
  int loop_count = -1;               // 0: forever
  std::vector<image::Image> frames;  // the whole canvas after each frame, RGBA
  std::vector<int> end_ms;           // when each frame ends, from the start
};

// Throws std::runtime_error when libwebp cannot read `bytes`.
WebpFrames decode_webp_frames(const std::string& bytes);

}  // namespace toond::test
