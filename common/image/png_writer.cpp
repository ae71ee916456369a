#include "image/png_writer.h"

#include <stdexcept>

namespace toond::image {
namespace {

void append_to_string(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

}  // namespace

void throw_png_error(png_structp, png_const_charp message) { throw std::runtime_error(std::string("png: ") + message); }

void ignore_png_warning(png_structp, png_const_charp) {}

PngWriter::PngWriter() {
  png_ = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, throw_png_error, ignore_png_warning);
  if (!png_) throw std::runtime_error("png: cannot create write struct");
  info_ = png_create_info_struct(png_);
  if (!info_) {
    png_destroy_write_struct(&png_, nullptr);
    throw std::runtime_error("png: cannot create info struct");
  }
  png_set_write_fn(png_, &out_, append_to_string, nullptr);
}

PngWriter::~PngWriter() { png_destroy_write_struct(&png_, &info_); }

void PngWriter::set_text(const TextChunks& text) {
  std::vector<png_text> chunks;
  for (const auto& [key, value] : text) {
    png_text chunk{};
    chunk.compression = PNG_TEXT_COMPRESSION_NONE;
    chunk.key = const_cast<png_charp>(key.c_str());
    chunk.text = const_cast<png_charp>(value.c_str());
    chunk.text_length = value.size();
    chunks.push_back(chunk);
  }
  if (!chunks.empty()) png_set_text(png_, info_, chunks.data(), static_cast<int>(chunks.size()));
}

std::string PngWriter::write_rows(const std::vector<const unsigned char*>& rows) {
  png_write_info(png_, info_);
  for (const unsigned char* row : rows) png_write_row(png_, row);
  png_write_end(png_, nullptr);
  return std::move(out_);
}

}  // namespace toond::image
