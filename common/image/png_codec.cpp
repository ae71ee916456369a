#include "image/png_codec.h"

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "image/deflate_strips.h"
#include "image/palette.h"
#include "image/png_writer.h"
#include "image/sub_filter.h"
#include "parallel/parallel_tasks.h"

namespace toond::image {
namespace {

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

// Level 0 stores. Levels 1 to 3 take the run encoder (run_deflate.h): a
// toon frame's filtered rows are runs of one byte (palette indices of one
// band; zeros where Sub-filtered truecolour is flat), which it finds as well
// as zlib's fastest search does, several times faster. From level 4 up the
// caller asked for size over speed and gets zlib's full search at that level.
DeflateMethod deflate_method(int level) { return level >= 1 && level <= 3 ? DeflateMethod::Runs : DeflateMethod::Zlib; }

// Below this many scanline bytes a strip costs more in setup than it saves:
// for zlib its state, about 256 KiB to allocate and clear; for the run
// encoder a block header and Huffman codes of its own (about 12 us).
constexpr std::size_t kMinStripBytes = 64 * 1024;
// The strip count depends on the image alone, never on the machine or on
// how many threads run, so a render's PNG is the same bytes everywhere (its
// ETag and cached answer with it). Eight strips keep every core of a small
// machine busy and leave a caller whose helper the scheduler has paused
// (another process has its core) waiting for one small strip at most, the
// caller taking whatever strips are left.
constexpr int kMaxStrips = 8;

int usable_threads(const PngOptions& options) {
  return options.threads <= 0 ? parallel::hardware_threads() : std::min(options.threads, parallel::hardware_threads());
}

// How many parts `bytes` of work are cut into: the deflate's strips, and
// the opacity check's parts over the pixels.
int strip_count(std::size_t bytes) {
  return static_cast<int>(std::clamp<std::size_t>(bytes / kMinStripBytes, 1, kMaxStrips));
}

DeflateSettings deflate_settings(const PngOptions& options, std::size_t scanline_bytes) {
  const int level = std::clamp(options.compression_level, 0, 9);
  const int strips = strip_count(scanline_bytes);
  return {deflate_method(level), level, Z_DEFAULT_STRATEGY, strips, std::min(usable_threads(options), strips)};
}

void set_palette(png_structp png, png_infop info, const Palette& palette) {
  std::vector<png_color> colours;
  std::vector<png_byte> alphas;
  for (const Rgba8& c : palette.colours()) {
    colours.push_back({c.r, c.g, c.b});
    if (alphas.size() < static_cast<std::size_t>(palette.translucent_count())) alphas.push_back(c.a);
  }
  png_set_PLTE(png, info, colours.data(), static_cast<int>(colours.size()));
  if (!alphas.empty()) png_set_tRNS(png, info, alphas.data(), static_cast<int>(alphas.size()), nullptr);
}

// libpng writes the container: signature, header, palette, colour space
// chunks, the IDAT holding the zlib stream made here, and the end.
std::string write_png(const Image& image, int colour_type, const Palette* palette, const std::string& idat,
                      const TextChunks& text) {
  PngWriter writer;
  writer.bytes().reserve(idat.size() + 256 + (palette ? 4 * palette->colours().size() : 0));
  png_set_IHDR(writer.png(), writer.info(), static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, colour_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (palette) set_palette(writer.png(), writer.info(), *palette);
  png_set_sRGB_gAMA_and_cHRM(writer.png(), writer.info(), PNG_sRGB_INTENT_PERCEPTUAL);
  writer.set_text(text);
  png_write_info(writer.png(), writer.info());
  png_write_chunk(writer.png(), reinterpret_cast<png_const_bytep>("IDAT"),
                  reinterpret_cast<png_const_bytep>(idat.data()), idat.size());
  png_write_chunk(writer.png(), reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
  return std::move(writer.bytes());
}

}  // namespace

std::string encode_png(const Image& image, const PngOptions& options) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw std::runtime_error("png: image size does not match its pixel buffer");
  }
  const int threads = usable_threads(options);
  if (const auto palette = find_palette(image, threads)) {
    const ScanlineSource rows = [&](int first_row, int row_count, std::vector<std::uint8_t>& scratch) {
      return palette->index_rows(image, first_row, row_count, scratch);
    };
    const std::size_t scanline_bytes = static_cast<std::size_t>(image.width) + 1;
    const std::string idat =
        deflate_scanlines(image.height, scanline_bytes, rows, deflate_settings(options, scanline_bytes * image.height));
    return write_png(image, PNG_COLOR_TYPE_PALETTE, &*palette, idat, options.text);
  }
  const TruecolourLayout layout =
      is_opaque(image, strip_count(image.rgba.size()), threads) ? TruecolourLayout::Rgb : TruecolourLayout::Rgba;
  const ScanlineSource rows = [&](int first_row, int row_count, std::vector<std::uint8_t>& scratch) {
    return sub_filtered_rows(image, layout, first_row, row_count, scratch);
  };
  const std::size_t scanline_bytes = static_cast<std::size_t>(image.width) * bytes_per_pixel(layout) + 1;
  const std::string idat =
      deflate_scanlines(image.height, scanline_bytes, rows, deflate_settings(options, scanline_bytes * image.height));
  return write_png(image, layout == TruecolourLayout::Rgb ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, nullptr, idat,
                   options.text);
}

Image decode_png(std::string_view bytes) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0) {
    throw std::runtime_error("png: not a PNG file");
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, throw_png_error, ignore_png_warning);
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
