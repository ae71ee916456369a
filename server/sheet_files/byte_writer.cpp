#include "sheet_files/byte_writer.h"

#include <algorithm>

namespace toond::sheet_files {

void ByteWriter::u8(std::uint8_t value) { bytes_.push_back(static_cast<char>(value)); }

void ByteWriter::u16(std::uint16_t value) {
  u8(static_cast<std::uint8_t>(value));
  u8(static_cast<std::uint8_t>(value >> 8));
}

void ByteWriter::i16(std::int16_t value) { u16(static_cast<std::uint16_t>(value)); }

void ByteWriter::u32(std::uint32_t value) {
  u16(static_cast<std::uint16_t>(value));
  u16(static_cast<std::uint16_t>(value >> 16));
}

void ByteWriter::i32(std::int32_t value) { u32(static_cast<std::uint32_t>(value)); }

void ByteWriter::zeros(std::size_t count) { bytes_.append(count, '\0'); }

void ByteWriter::bytes(std::string_view data) { bytes_.append(data); }

void ByteWriter::string(std::string_view text) {
  const std::size_t length = std::min<std::size_t>(text.size(), 0xFFFF);
  u16(static_cast<std::uint16_t>(length));
  bytes_.append(text.substr(0, length));
}

void ByteWriter::patch_u16(std::size_t offset, std::uint16_t value) {
  bytes_[offset] = static_cast<char>(value & 0xFF);
  bytes_[offset + 1] = static_cast<char>(value >> 8);
}

void ByteWriter::patch_u32(std::size_t offset, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes_[offset + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
}

}  // namespace toond::sheet_files
