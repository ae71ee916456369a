#include "support/stored_zip.h"

#include <zlib.h>

#include <cstdint>

namespace toond::test {
namespace {

void put16(std::string& out, unsigned v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>((v >> 8) & 0xff));
}

void put32(std::string& out, std::uint32_t v) {
  put16(out, v & 0xffff);
  put16(out, v >> 16);
}

// The fields a local header and a central-directory entry share, from
// "version needed" to the name's length (the extra field is empty).
void common_fields(std::string& out, std::uint32_t crc, std::size_t size, std::size_t name) {
  put16(out, 20);    // version needed: 2.0
  put16(out, 0);     // flags
  put16(out, 0);     // method: stored
  put16(out, 0);     // time
  put16(out, 0x21);  // date: 1980-01-01
  put32(out, crc);
  put32(out, static_cast<std::uint32_t>(size));  // compressed
  put32(out, static_cast<std::uint32_t>(size));  // uncompressed
  put16(out, static_cast<unsigned>(name));
  put16(out, 0);  // extra field
}

}  // namespace

std::string stored_zip(const std::vector<std::pair<std::string, std::string>>& files) {
  std::string zip, directory;
  for (const auto& [name, content] : files) {
    const std::uint32_t crc = static_cast<std::uint32_t>(
        crc32(0, reinterpret_cast<const Bytef*>(content.data()), static_cast<uInt>(content.size())));
    const std::size_t offset = zip.size();
    put32(zip, 0x04034b50);
    common_fields(zip, crc, content.size(), name.size());
    zip += name;
    zip += content;
    put32(directory, 0x02014b50);
    put16(directory, 20);  // made by: 2.0
    common_fields(directory, crc, content.size(), name.size());
    put16(directory, 0);  // comment
    put16(directory, 0);  // disk
    put16(directory, 0);  // internal attributes
    put32(directory, 0);  // external attributes
    put32(directory, static_cast<std::uint32_t>(offset));
    directory += name;
  }
  const std::size_t directory_offset = zip.size();
  zip += directory;
  put32(zip, 0x06054b50);
  put16(zip, 0);
  put16(zip, 0);
  put16(zip, static_cast<unsigned>(files.size()));
  put16(zip, static_cast<unsigned>(files.size()));
  put32(zip, static_cast<std::uint32_t>(directory.size()));
  put32(zip, static_cast<std::uint32_t>(directory_offset));
  put16(zip, 0);  // comment
  return zip;
}

}  // namespace toond::test
