#pragma once
// Little-endian fields appended to a byte string, and sizes written back
// once what they measure is written: how .aseprite chunks are laid down.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace toond::sheet_files {

class ByteWriter {
 public:
  void u8(std::uint8_t value);
  void u16(std::uint16_t value);
  void i16(std::int16_t value);
  void u32(std::uint32_t value);
  void i32(std::int32_t value);
  void zeros(std::size_t count);
  void bytes(std::string_view data);
  // Aseprite's STRING: a 16-bit byte count, then UTF-8 without a 0 (cut at
  // 65535 bytes).
  void string(std::string_view text);

  std::size_t size() const { return bytes_.size(); }
  // Overwrite the field at `offset`, written earlier.
  void patch_u16(std::size_t offset, std::uint16_t value);
  void patch_u32(std::size_t offset, std::uint32_t value);
  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

}  // namespace toond::sheet_files
