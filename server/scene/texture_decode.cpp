#include "scene/texture_decode.h"

#include <climits>
#include <cstring>
#include <memory>
#include <stdexcept>

#include <stb_image.h>

namespace toond::scene {

Texture decode_texture(std::string_view bytes, const std::string& path, const TextureLimits& limits) {
  if (bytes.empty()) throw std::runtime_error("the file is empty");
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw std::runtime_error("the file is too large");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());

  int width = 0;
  int height = 0;
  int channels = 0;
  if (!stbi_info_from_memory(data, length, &width, &height, &channels)) {
    throw std::runtime_error(std::string("not a readable image (") + stbi_failure_reason() + ")");
  }
  if (width <= 0 || height <= 0) throw std::runtime_error("the image has no pixels");
  if (width > limits.max_dimension || height > limits.max_dimension ||
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) > limits.max_pixels) {
    throw std::runtime_error("the image is " + std::to_string(width) + "x" + std::to_string(height) +
                             ", larger than the limit of " + std::to_string(limits.max_dimension) + " per side and " +
                             std::to_string(limits.max_pixels) + " pixels");
  }

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
  return texture;
}

}  // namespace toond::scene
