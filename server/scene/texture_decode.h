#pragma once
// Decoding of the image files a material names (PNG, JPEG, TGA, BMP, ...)
// into the importer's RGBA8 textures.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "scene/model.h"

namespace toond::scene {

// An upload is untrusted: the header is checked against these before any
// pixel memory is allocated, so a tiny file cannot claim gigabytes.
struct TextureLimits {
  int max_dimension = 16384;  // GL's usual largest texture side
  std::uint64_t max_pixels = 64ull * 1024 * 1024;
};

// The header gave a size over the limits; nothing was decoded.
class TextureTooLarge : public std::runtime_error {
 public:
  TextureTooLarge(int width, int height, const std::string& message)
      : std::runtime_error(message), width_(width), height_(height) {}
  std::uint64_t pixels() const { return static_cast<std::uint64_t>(width_) * static_cast<std::uint64_t>(height_); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_;
  int height_;
};

// Decodes `bytes` into an RGBA8 texture (values left as stored, 16-bit
// images reduced to 8 bits; color_space is Srgb, and an importer reading a
// data map such as a normal map sets Linear). `path` is recorded in the result.
// Throws std::runtime_error with a reason when the format is unknown, the
// data is corrupt; TextureTooLarge (from the header alone) when the image
// exceeds `limits`.
Texture decode_texture(std::string_view bytes, const std::string& path, const TextureLimits& limits = {});

}  // namespace toond::scene
