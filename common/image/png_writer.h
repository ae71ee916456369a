#pragma once
// libpng's write side for the encoders that hand it whole rows (the data
// layers: 16-bit grey, palette indices chosen by the caller), with the
// error handling and the tEXt chunks every toond PNG shares.
#include <png.h>

#include <string>

#include "image/png_codec.h"

namespace toond::image {

// libpng reports errors through longjmp by default; a C++ exception thrown
// from the error callback unwinds cleanly instead (libpng is built to allow it).
[[noreturn]] void throw_png_error(png_structp png, png_const_charp message);
void ignore_png_warning(png_structp png, png_const_charp message);

// Owns one libpng write struct that appends to a string.
class PngWriter {
 public:
  PngWriter();
  ~PngWriter();
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;

  png_structp png() const { return png_; }
  png_infop info() const { return info_; }
  // libpng copies the text when it is set.
  void set_text(const TextChunks& text);
  // Writes the header chunks set so far, then `rows` (each a whole
  // scanline in PNG byte order) and the end; returns the file.
  std::string write_rows(const std::vector<const unsigned char*>& rows);
  // What has been written so far (write_png in png_codec writes its own
  // IDAT and ends the file itself).
  std::string& bytes() { return out_; }

 private:
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
  std::string out_;
};

}  // namespace toond::image
