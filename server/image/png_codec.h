#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "image/image.h"

namespace toond::image {

struct PngOptions {
  // zlib level 0..9. Toon images are large flat areas; a low level with the
  // SUB filter and run-length strategy is much faster at nearly the same size.
  int compression_level = 3;
  // tEXt chunks (key, Latin-1 text), written ahead of the pixels: a sprite
  // sheet carries its atlas this way.
  std::vector<std::pair<std::string, std::string>> text{};
};

// Encodes to PNG (RGBA, 8 bits). Throws std::runtime_error on failure.
std::string encode_png(const Image& image, const PngOptions& options = {});

// Decodes any 8-bit or 16-bit PNG to RGBA8. Throws std::runtime_error with
// libpng's message on malformed input.
Image decode_png(std::string_view bytes);

}  // namespace toond::image
