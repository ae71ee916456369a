// libFuzzer target: images through the PNG encoder and back. The first
// bytes choose the width, the compression level and how many strips the
// scanlines are cut into; the rest are RGBA pixels, so the fuzzer reaches
// every layout (palette, RGB, RGBA) and both deflaters. A PNG that does not
// decode to the image, or a strip stream that does not inflate to its
// input, is a finding; so is any exception, since every image is encodable.
#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <span>

#include "image/deflate_strips.h"
#include "image/png_codec.h"

namespace {

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "fuzz_png_encode: %s\n", what);
  std::abort();
}

void check_png_round_trip(const toond::image::Image& image, int level) {
  const std::string png = toond::image::encode_png(image, {level, 2, {}});
  if (toond::image::decode_png(png).rgba != image.rgba) finding("the PNG does not decode to the image");
}

// The raw pixel bytes as scanlines of `width` bytes through the run
// deflater in `strips` strips, inflated again by zlib.
void check_strips_round_trip(std::span<const std::uint8_t> bytes, int width, int strips) {
  const int rows = static_cast<int>(bytes.size()) / width;
  if (rows == 0) return;
  const toond::image::ScanlineSource source = [&](int first, int count, std::vector<std::uint8_t>&) {
    return bytes.subspan(static_cast<std::size_t>(first) * width, static_cast<std::size_t>(count) * width);
  };
  const std::string stream = toond::image::deflate_scanlines(rows, static_cast<std::size_t>(width), source,
                                                             {toond::image::DeflateMethod::Runs, 1, 0, strips, 2});
  std::vector<std::uint8_t> out(static_cast<std::size_t>(rows) * width + 1);
  uLongf size = static_cast<uLongf>(out.size());
  if (uncompress(out.data(), &size, reinterpret_cast<const Bytef*>(stream.data()), static_cast<uLong>(stream.size())) !=
          Z_OK ||
      size != static_cast<uLongf>(rows) * width ||
      !std::equal(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(size), bytes.begin())) {
    finding("the strips do not inflate to their scanlines");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const int width = 1 + data[0] % 64;
  const int level = data[1] % 10;
  const int strips = 1 + data[2] % 9;
  const std::span<const std::uint8_t> pixels(data + 3, size - 3);
  try {
    toond::image::Image image;
    image.width = width;
    image.height = static_cast<int>(pixels.size() / (4 * static_cast<std::size_t>(width)));
    if (image.height > 0) {
      image.rgba.assign(pixels.begin(), pixels.begin() + static_cast<std::ptrdiff_t>(4 * width * image.height));
      check_png_round_trip(image, level);
    }
    check_strips_round_trip(pixels, width, strips);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_png_encode: unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
