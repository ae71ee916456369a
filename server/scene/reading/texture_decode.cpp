#include "scene/reading/texture_decode.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include <stb_image.h>
#include <webp/decode.h>

#include "scene/reading/import_limits.h"

namespace toond::scene {
namespace {

void check_limits(std::uint64_t width, std::uint64_t height, const TextureLimits& limits) {
  const auto side = static_cast<std::uint64_t>(limits.max_dimension);
  if (width > side || height > side || width * height > limits.max_pixels) {
    const auto w = static_cast<int>(std::min<std::uint64_t>(width, INT_MAX));
    const auto h = static_cast<int>(std::min<std::uint64_t>(height, INT_MAX));
    throw TextureTooLarge(w, h,
                          "the image is " + std::to_string(width) + "x" + std::to_string(height) +
                              ", larger than the limit of " + std::to_string(limits.max_dimension) + " per side and " +
                              std::to_string(limits.max_pixels) + " pixels");
  }
}

// Width and height from a PNG's IHDR chunk (big-endian, right after the
// 8-byte signature and the chunk's length and type), when it is a PNG.
std::optional<std::pair<std::uint64_t, std::uint64_t>> png_header_size(std::string_view bytes) {
  static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.size() < 24 || bytes.substr(0, 8) != kSignature || bytes.substr(12, 4) != "IHDR") return std::nullopt;
  const auto be32 = [&](std::size_t at) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return std::make_pair(be32(16), be32(20));
}

bool is_webp(std::string_view bytes) {
  return bytes.size() >= 12 && bytes.substr(0, 4) == "RIFF" && bytes.substr(8, 4) == "WEBP";
}

// stb_image reads no WebP; glTF's EXT_texture_webp carries it.
Texture decode_webp(std::string_view bytes, const std::string& path, const TextureLimits& limits) {
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  int width = 0;
  int height = 0;
  if (!WebPGetInfo(data, bytes.size(), &width, &height) || width <= 0 || height <= 0) {
    throw std::runtime_error("not a readable WebP image");
  }
  check_limits(static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(height), limits);
  Texture texture;
  texture.path = path;
  texture.width = width;
  texture.height = height;
  texture.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  const int stride = width * 4;
  if (!WebPDecodeRGBAInto(data, bytes.size(), texture.rgba.data(), texture.rgba.size(), stride)) {
    throw std::runtime_error("cannot decode the WebP image");
  }
  return texture;
}

std::uint8_t lowest_alpha(const std::vector<std::uint8_t>& rgba) {
  std::uint8_t lowest = 255;
  for (std::size_t i = 3; i < rgba.size(); i += 4) lowest = std::min(lowest, rgba[i]);
  return lowest;
}

}  // namespace

Texture decode_texture(std::string_view bytes, const std::string& path, const TextureLimits& limits) {
  if (bytes.empty()) throw std::runtime_error("the file is empty");
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw std::runtime_error("the file is too large");
  if (is_webp(bytes)) {
    Texture texture = decode_webp(bytes, path, limits);
    texture.min_alpha = lowest_alpha(texture.rgba);
    return texture;
  }
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());

  int width = 0;
  int height = 0;
  int channels = 0;
  if (const auto size = png_header_size(bytes)) {
    // stb_image's own header check refuses very large PNGs as "unknown image
    // type"; read the size first so the answer says what is wrong.
    check_limits(size->first, size->second, limits);
  }
  if (!stbi_info_from_memory(data, length, &width, &height, &channels)) {
    throw std::runtime_error(std::string("not a readable image (") + stbi_failure_reason() + ")");
  }
  if (width <= 0 || height <= 0) throw std::runtime_error("the image has no pixels");
  check_limits(width, height, limits);

  int decoded_w = 0;
  int decoded_h = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(data, length, &decoded_w, &decoded_h, &channels, STBI_rgb_alpha), stbi_image_free);
  if (!pixels) throw std::runtime_error(std::string("cannot decode the image (") + stbi_failure_reason() + ")");
  // The header already passed the limits; a decoder that disagrees with its
  // own header is not trusted with a buffer size.
  if (decoded_w != width || decoded_h != height) throw std::runtime_error("the image's size changed while decoding");

  Texture texture;
  texture.path = path;
  texture.width = width;
  texture.height = height;
  texture.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  std::memcpy(texture.rgba.data(), pixels.get(), texture.rgba.size());
  texture.min_alpha = lowest_alpha(texture.rgba);
  return texture;
}

Texture decode_model_texture(std::string_view bytes, const std::string& path, std::uint64_t max_texture_pixels,
                             std::uint64_t& pixels_left) {
  TextureLimits limits;
  limits.max_pixels = std::min(max_texture_pixels, pixels_left);
  try {
    Texture texture = decode_texture(bytes, path, limits);
    pixels_left -= static_cast<std::uint64_t>(texture.width) * static_cast<std::uint64_t>(texture.height);
    return texture;
  } catch (const TextureTooLarge& e) {
    // Over the daemon's limit for one image: the upload is refused, so the
    // client learns which file to shrink. Over what is left of the model's
    // total, the caller leaves the texture out.
    if (e.pixels() > max_texture_pixels) {
      throw ImportLimitError(path, ImportLimit::TexturePixels, static_cast<double>(max_texture_pixels),
                             path + ": the image is " + std::to_string(e.width()) + "x" + std::to_string(e.height()) +
                                 " = " + std::to_string(e.pixels()) + " pixels, more than");
    }
    throw;
  }
}

}  // namespace toond::scene
