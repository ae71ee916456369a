#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "image/image.h"

namespace toond::image {

// tEXt chunks: (key, Latin-1 text) pairs.
using TextChunks = std::vector<std::pair<std::string, std::string>>;

struct PngOptions {
  // 0..9: 0 stores (largest); 1 to 3 the run encoder (run_deflate.h),
  // the fastest, nearly as small as a full search on toon frames; 4 to 9
  // zlib's full search at that level (smaller, slower).
  int compression_level = 3;
  // At most this many threads deflate at once; 0 or more than the hardware
  // has: one per hardware thread.
  int threads = 0;
  // tEXt chunks (key, Latin-1 text), written ahead of the pixels: a sprite
  // sheet carries its atlas this way.
  TextChunks text{};
};

// Encodes to PNG, 8 bits per channel, in the smallest layout that holds the
// image exactly; whichever is chosen, decoding gives back the same RGBA bytes:
//  - at most 256 distinct RGBA values: a palette (colour type 3), one byte a
//    pixel, with a tRNS chunk when any colour is translucent; rows unfiltered,
//    as palette indices have no numeric order for a filter to exploit;
//  - otherwise, every alpha 255: RGB (colour type 2), else RGBA (6); rows Sub
//    filtered, which turns flat bands into runs of zeros.
// The zlib stream is made here rather than by libpng so that it can be cut
// into horizontal strips (64 KiB of scanlines at least, at most eight, a
// count that depends on the image alone so the bytes are the same on every
// machine) deflated on several cores at once, one thread per hardware
// thread at most, the caller included, by the run encoder at levels 1 to 3
// (run_deflate.h); libpng still writes every chunk. The palette is counted
// the same way, in bands. Throws std::runtime_error on failure.
std::string encode_png(const Image& image, const PngOptions& options = {});

// Decodes any 8-bit or 16-bit PNG to RGBA8. Throws std::runtime_error with
// libpng's message on malformed input.
Image decode_png(std::string_view bytes);

}  // namespace toond::image
