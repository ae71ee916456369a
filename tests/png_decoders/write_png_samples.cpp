// Writes PNGs made by encode_png beside the raw RGBA they must decode to, so
// that decoders other than ours can check them (pil_decodes_samples.py).
//   toond_png_samples OUT_DIR [FRAME.png ...]
// For each sample NAME: NAME.png, NAME.rgba (width * height * 4 bytes, rows
// top to bottom) and a line "NAME WIDTH HEIGHT COLOUR_TYPE" in samples.txt.
// FRAME.png files (rendered frames, say) are decoded and written again.
// Exits 1 when a sample is not written in the PNG colour type expected of
// it (a palette for at most 256 colours, RGB for opaque images).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "image/png_codec.h"

namespace {

using toond::image::Image;

// PNG colour types (IHDR byte 25).
constexpr int kRgb = 2, kPalette = 3, kRgba = 6, kAnyType = -1;

Image blank(int w, int h) { return {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)}; }

// `colours` distinct colours in turn; alpha varies when `translucent`.
Image cycling(int w, int h, int colours, bool translucent) {
  Image img = blank(w, h);
  for (int i = 0; i < w * h; ++i) {
    const int c = i % colours;
    std::uint8_t* p = img.rgba.data() + static_cast<std::size_t>(i) * 4;
    p[0] = static_cast<std::uint8_t>(c * 37);
    p[1] = static_cast<std::uint8_t>(c / 5);
    p[2] = static_cast<std::uint8_t>(c * 11);
    p[3] = translucent ? static_cast<std::uint8_t>(c * 3 % 256) : 255;
  }
  return img;
}

Image noise(int w, int h, bool opaque, unsigned seed) {
  std::mt19937 random(seed);
  Image img = blank(w, h);
  for (std::size_t i = 0; i < img.rgba.size(); ++i) {
    img.rgba[i] = (opaque && i % 4 == 3) ? 255 : static_cast<std::uint8_t>(random());
  }
  return img;
}

// A flat disc on a flat background with an antialiased rim whose coverage
// has `rim_levels` steps: few levels fit a palette, many do not. A
// transparent background makes the rim translucent too.
Image disc(int size, int rim_levels, bool transparent_background) {
  Image img = blank(size, size);
  const double r = size * 0.4, c = size * 0.5;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double d = std::hypot(x + 0.5 - c, y + 0.5 - c);
      const double cover = std::clamp(r - d + 0.5, 0.0, 1.0);
      const double level = std::round(cover * rim_levels) / rim_levels;
      std::uint8_t* p = img.pixel(x, y);
      const double bg[4] = {235, 235, 240, transparent_background ? 0.0 : 255.0};
      const double fg[4] = {200.0 + x * 4 / size, 120, 90.0 + y % 3, 255};
      for (int k = 0; k < 4; ++k) p[k] = static_cast<std::uint8_t>(std::lround(bg[k] + (fg[k] - bg[k]) * level));
    }
  }
  return img;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class SampleWriter {
 public:
  explicit SampleWriter(std::filesystem::path dir) : dir_(std::move(dir)), list_(dir_ / "samples.txt") {}

  void write(const std::string& name, const Image& image, int expected_colour_type,
             const toond::image::PngOptions& options = {}) {
    const std::string png = toond::image::encode_png(image, options);
    const int colour_type = static_cast<unsigned char>(png.at(25));
    if (expected_colour_type != kAnyType && colour_type != expected_colour_type) {
      throw std::runtime_error(name + ": PNG colour type " + std::to_string(colour_type) + ", expected " +
                               std::to_string(expected_colour_type));
    }
    std::ofstream(dir_ / (name + ".png"), std::ios::binary) << png;
    std::ofstream(dir_ / (name + ".rgba"), std::ios::binary)
        .write(reinterpret_cast<const char*>(image.rgba.data()), static_cast<std::streamsize>(image.rgba.size()));
    list_ << name << ' ' << image.width << ' ' << image.height << ' ' << colour_type << '\n';
  }

 private:
  std::filesystem::path dir_;
  std::ofstream list_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: toond_png_samples OUT_DIR [FRAME.png ...]\n";
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    SampleWriter samples(dir);
    samples.write("palette-opaque", cycling(61, 47, 200, false), kPalette);
    samples.write("palette-translucent", cycling(64, 40, 150, true), kPalette);
    samples.write("palette-256", cycling(256, 3, 256, false), kPalette);
    samples.write("rgb-257", cycling(257, 3, 257, false), kRgb);
    samples.write("rgba-257", cycling(257, 3, 257, true), kRgba);
    samples.write("one-pixel-opaque", {1, 1, {10, 20, 30, 255}}, kPalette);
    samples.write("one-pixel-translucent", {1, 1, {10, 20, 30, 99}}, kPalette);
    samples.write("tall-noise", noise(1, 777, false, 1), kRgba);
    samples.write("wide-palette", cycling(777, 1, 9, true), kPalette);
    samples.write("odd-noise-rgb", noise(513, 257, true, 2), kRgb);
    samples.write("noise-rgba", noise(300, 200, false, 3), kRgba);
    samples.write("disc-palette", disc(512, 8, false), kPalette);
    samples.write("disc-rgb", disc(512, 255, false), kRgb);
    samples.write("disc-palette-transparent", disc(512, 8, true), kPalette);
    samples.write("disc-rgba-transparent", disc(512, 255, true), kRgba);
    // Cut into strips deflated on two threads where the machine has two
    // cores (encode_png never runs more threads than there are).
    for (int threads : {1, 2}) {
      const std::string suffix = "-threads" + std::to_string(threads);
      samples.write("big-disc-rgb" + suffix, disc(1024, 255, false), kRgb, {3, threads});
      samples.write("big-disc-palette" + suffix, disc(1024, 8, false), kPalette, {3, threads});
      samples.write("big-noise-level9" + suffix, noise(700, 400, false, 4), kRgba, {9, threads});
    }
    for (int i = 2; i < argc; ++i) {
      const std::filesystem::path frame = argv[i];
      samples.write("frame-" + frame.stem().string(), toond::image::decode_png(read_file(frame)), kAnyType);
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "toond_png_samples: " << e.what() << "\n";
    return 1;
  }
}
