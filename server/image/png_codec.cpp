#include "image/png_codec.h"

#include <png.h>
#include <zlib.h>

#include <cstring>
#include <stdexcept>

namespace toond::image {
namespace {

// libpng reports errors through longjmp by default; a C++ exception thrown
// from the error callback unwinds cleanly instead (libpng is built to allow it).
[[noreturn]] void throw_png_error(png_structp, png_const_charp message) {
  throw std::runtime_error(std::string("png: ") + message);
}
void ignore_png_warning(png_structp, png_const_charp) {}

void append_to_string(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

struct ReadCursor {
  std::string_view bytes;
  std::size_t offset = 0;
};

void read_from_view(png_structp png, png_bytep data, png_size_t length) {
  auto* cursor = static_cast<ReadCursor*>(png_get_io_ptr(png));
  if (cursor->bytes.size() - cursor->offset < length) throw_png_error(png, "truncated data");
  std::memcpy(data, cursor->bytes.data() + cursor->offset, length);
  cursor->offset += length;
}

// libpng copies the text when it is set, so the pointers need only live
// through this call.
void set_text_chunks(png_structp png, png_infop info,
                     const std::vector<std::pair<std::string, std::string>>& text) {
  std::vector<png_text> chunks;
  for (const auto& [key, value] : text) {
    png_text chunk{};
    chunk.compression = PNG_TEXT_COMPRESSION_NONE;
    chunk.key = const_cast<png_charp>(key.c_str());
    chunk.text = const_cast<png_charp>(value.c_str());
    chunk.text_length = value.size();
    chunks.push_back(chunk);
  }
  if (!chunks.empty()) png_set_text(png, info, chunks.data(), static_cast<int>(chunks.size()));
}

}  // namespace

std::string encode_png(const Image& image, const PngOptions& options) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw std::runtime_error("png: image size does not match its pixel buffer");
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, throw_png_error,
                                            ignore_png_warning);
  if (!png) throw std::runtime_error("png: cannot create write struct");
  png_infop info = png_create_info_struct(png);
  std::string out;
  try {
    if (!info) throw std::runtime_error("png: cannot create info struct");
    png_set_write_fn(png, &out, append_to_string, nullptr);
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
                 static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    set_text_chunks(png, info, options.text);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_compression_level(png, options.compression_level);
    png_set_compression_strategy(png, Z_RLE);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) {
      png_write_row(png, const_cast<png_bytep>(image.pixel(0, y)));
    }
    png_write_end(png, nullptr);
  } catch (...) {
    png_destroy_write_struct(&png, &info);
    throw;
  }
  png_destroy_write_struct(&png, &info);
  return out;
}

Image decode_png(std::string_view bytes) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0) {
    throw std::runtime_error("png: not a PNG file");
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, throw_png_error,
                                           ignore_png_warning);
  if (!png) throw std::runtime_error("png: cannot create read struct");
  png_infop info = png_create_info_struct(png);
  Image image;
  ReadCursor cursor{bytes, 0};
  try {
    if (!info) throw std::runtime_error("png: cannot create info struct");
    png_set_read_fn(png, &cursor, read_from_view);
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    image.width = static_cast<int>(png_get_image_width(png, info));
    image.height = static_cast<int>(png_get_image_height(png, info));
    image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
    for (int y = 0; y < image.height; ++y) rows[static_cast<std::size_t>(y)] = image.pixel(0, y);
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
  } catch (...) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw;
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

}  // namespace toond::image
