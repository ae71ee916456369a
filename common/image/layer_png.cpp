#include "image/layer_png.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "image/image.h"
#include "image/png_codec.h"

namespace toond::image {
namespace {

constexpr std::uint16_t kDepthBackground = 65535;
constexpr float kDepthFarthest = 65534.0f;

void check_size(const FloatImage& layer) {
  if (layer.width <= 0 || layer.height <= 0 ||
      layer.values.size() != static_cast<std::size_t>(layer.width) * layer.height * 4) {
    throw std::runtime_error("png: layer size does not match its values");
  }
}

void set_header(PngWriter& writer, const FloatImage& layer, int bit_depth, int colour_type, int compression_level) {
  png_set_IHDR(writer.png(), writer.info(), static_cast<png_uint_32>(layer.width),
               static_cast<png_uint_32>(layer.height), bit_depth, colour_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(writer.png(), std::clamp(compression_level, 0, 9));
}

std::vector<const unsigned char*> row_pointers(const std::vector<unsigned char>& bytes, int height,
                                               std::size_t row_bytes) {
  std::vector<const unsigned char*> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) rows[static_cast<std::size_t>(y)] = bytes.data() + y * row_bytes;
  return rows;
}

std::uint16_t depth_sample(float depth, const DepthRange& range) {
  const float span = range.far_depth - range.near_depth;
  if (span <= 0.0f) return 0;
  const float t = std::clamp((depth - range.near_depth) / span, 0.0f, 1.0f);
  return static_cast<std::uint16_t>(std::lround(t * kDepthFarthest));
}

std::uint8_t unit_to_byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
}

// Hues a golden angle apart: neighbouring ids never look alike, and the
// colours do not depend on how many ids there are.
png_color id_colour(int id) {
  const double hue = std::fmod(id * 137.50776405, 360.0) / 60.0;
  const double lightness = id % 2 ? 0.55 : 0.4;
  const double chroma = (1.0 - std::abs(2.0 * lightness - 1.0)) * 0.85;
  const double x = chroma * (1.0 - std::abs(std::fmod(hue, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0:
      r = chroma, g = x;
      break;
    case 1:
      r = x, g = chroma;
      break;
    case 2:
      g = chroma, b = x;
      break;
    case 3:
      g = x, b = chroma;
      break;
    case 4:
      r = x, b = chroma;
      break;
    default:
      r = chroma, b = x;
      break;
  }
  const double m = lightness - chroma / 2.0;
  const auto byte = [&](double c) { return static_cast<png_byte>(std::lround(std::clamp(c + m, 0.0, 1.0) * 255.0)); };
  return {byte(r), byte(g), byte(b)};
}

}  // namespace

DepthRange visible_depth_range(const FloatImage& layer) {
  float nearest = std::numeric_limits<float>::infinity();
  float farthest = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i + 3 < layer.values.size(); i += 4) {
    if (layer.values[i + 3] <= 0.0f) continue;
    nearest = std::min(nearest, layer.values[i]);
    farthest = std::max(farthest, layer.values[i]);
  }
  if (nearest > farthest) return {};
  return {nearest, farthest};
}

std::string encode_depth_png(const FloatImage& layer, const DepthRange& range, int compression_level,
                             const TextChunks& text) {
  check_size(layer);
  const std::size_t row_bytes = static_cast<std::size_t>(layer.width) * 2;
  std::vector<unsigned char> bytes(row_bytes * layer.height);
  for (int y = 0; y < layer.height; ++y) {
    for (int x = 0; x < layer.width; ++x) {
      const std::uint16_t v = layer.covered(x, y) ? depth_sample(layer.pixel(x, y)[0], range) : kDepthBackground;
      // PNG stores 16-bit samples most significant byte first.
      unsigned char* out = bytes.data() + y * row_bytes + x * 2;
      out[0] = static_cast<unsigned char>(v >> 8);
      out[1] = static_cast<unsigned char>(v & 0xff);
    }
  }
  PngWriter writer;
  set_header(writer, layer, 16, PNG_COLOR_TYPE_GRAY, compression_level);
  writer.set_text(text);
  return writer.write_rows(row_pointers(bytes, layer.height, row_bytes));
}

std::string encode_normal_png(const FloatImage& layer, int compression_level, const TextChunks& text) {
  check_size(layer);
  Image image{layer.width, layer.height, std::vector<std::uint8_t>(layer.values.size(), 0)};
  for (int y = 0; y < layer.height; ++y) {
    for (int x = 0; x < layer.width; ++x) {
      if (!layer.covered(x, y)) continue;
      const float* n = layer.pixel(x, y);
      std::uint8_t* out = image.pixel(x, y);
      out[0] = unit_to_byte(n[0]);
      out[1] = unit_to_byte(n[1]);
      out[2] = unit_to_byte(n[2]);
      out[3] = 255;
    }
  }
  PngOptions options;
  options.compression_level = compression_level;
  options.text = text;
  return encode_png(image, options);
}

std::string encode_id_png(const FloatImage& layer, int id_count, int compression_level, const TextChunks& text) {
  check_size(layer);
  if (id_count < 0 || id_count > kMaxLayerIds) {
    throw std::runtime_error("png: an id layer holds at most 255 ids, not " + std::to_string(id_count));
  }
  const std::size_t row_bytes = static_cast<std::size_t>(layer.width);
  std::vector<unsigned char> bytes(row_bytes * layer.height, 0);
  for (int y = 0; y < layer.height; ++y) {
    for (int x = 0; x < layer.width; ++x) {
      if (!layer.covered(x, y)) continue;
      const long id = std::lround(layer.pixel(x, y)[0]);
      bytes[y * row_bytes + x] = static_cast<unsigned char>(std::clamp<long>(id, 0, id_count));
    }
  }
  std::vector<png_color> palette{{0, 0, 0}};
  for (int id = 1; id <= id_count; ++id) palette.push_back(id_colour(id));
  const png_byte background_alpha = 0;
  PngWriter writer;
  set_header(writer, layer, 8, PNG_COLOR_TYPE_PALETTE, compression_level);
  png_set_PLTE(writer.png(), writer.info(), palette.data(), static_cast<int>(palette.size()));
  png_set_tRNS(writer.png(), writer.info(), &background_alpha, 1, nullptr);
  writer.set_text(text);
  return writer.write_rows(row_pointers(bytes, layer.height, row_bytes));
}

}  // namespace toond::image
