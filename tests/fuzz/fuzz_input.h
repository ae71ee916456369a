#pragma once
// Splits one fuzzer input into named files, the form every toond fuzz
// target and its seed corpus share (readable, so seeds can be written by
// hand):
//
//   model.obj
//   v 0 0 0 ...
//   --file--
//   m.mtl
//   newmtl m ...
//
// Records are separated by a line "--file--"; a record's first line is its
// name, the rest its bytes. An input without a separator is one record.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace toond::fuzz {

inline std::vector<std::pair<std::string, std::string>> split_files(const std::uint8_t* data, std::size_t size) {
  static constexpr std::string_view kSeparator = "\n--file--\n";
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::vector<std::pair<std::string, std::string>> files;
  std::size_t pos = 0;
  while (pos <= input.size() && files.size() < 64) {
    const std::size_t end = std::min(input.find(kSeparator, pos), input.size());
    const std::string_view record = input.substr(pos, end - pos);
    const std::size_t newline = record.find('\n');
    files.emplace_back(std::string(record.substr(0, newline)),
                       newline == std::string_view::npos ? std::string() : std::string(record.substr(newline + 1)));
    if (end == input.size()) break;
    pos = end + kSeparator.size();
  }
  return files;
}

}  // namespace toond::fuzz
