#pragma once
// Decoding of the image files a material names (PNG, JPEG, TGA, BMP, WebP, ...)
// into the importer's RGBA8 textures.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "scene/mesh/model.h"

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

// All textures of one model together may hold this many pixels: many
// materials each naming a large image must not add up to more memory than
// one upload deserves (1 GiB of RGBA8).
inline constexpr std::uint64_t kModelTexturePixels = 256ull * 1024 * 1024;

// decode_texture for one of a model's textures: an image over
// `max_texture_pixels` (ImportLimits) is an ImportLimitError
// (ImportLimit::TexturePixels); one over `pixels_left` (what the model's
// earlier textures left of kModelTexturePixels) throws TextureTooLarge, so
// the importer can leave it out with a warning. On success its pixels are
// taken from `pixels_left`.
Texture decode_model_texture(std::string_view bytes, const std::string& path, std::uint64_t max_texture_pixels,
                             std::uint64_t& pixels_left);

}  // namespace toond::scene
