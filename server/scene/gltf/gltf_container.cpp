#include "scene/gltf/gltf_container.h"

#include <cstdint>

#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

constexpr std::string_view kMagic = "glTF";
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON", little-endian
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0", little-endian
constexpr std::size_t kHeaderSize = 12;
constexpr std::size_t kChunkHeaderSize = 8;

std::uint32_t le32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

}  // namespace

bool looks_like_gltf(std::string_view content) {
  if (content.starts_with(kMagic)) return true;
  if (content.starts_with("\xEF\xBB\xBF")) content.remove_prefix(3);
  const auto first = content.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && content[first] == '{' &&
         content.find("\"asset\"") != std::string_view::npos;
}

GltfContainer open_gltf_container(std::string_view content, const std::string& path) {
  if (!content.starts_with(kMagic)) {
    if (content.starts_with("\xEF\xBB\xBF")) content.remove_prefix(3);
    return {content, std::nullopt};
  }
  const auto fail = [&](const std::string& why) {
    throw ImportError(path, path + ": not a valid glTF binary: " + why);
  };
  if (content.size() < kHeaderSize + kChunkHeaderSize) fail("the file ends inside its header");
  if (le32(content, 4) != 2) fail("container version " + std::to_string(le32(content, 4)) + " (only 2 is read)");
  const std::uint64_t declared = le32(content, 8);
  if (declared > content.size()) {
    fail("the header declares " + std::to_string(declared) + " bytes but the file has " +
         std::to_string(content.size()) + " (truncated?)");
  }
  content = content.substr(0, static_cast<std::size_t>(declared));

  GltfContainer container;
  bool have_json = false;
  std::size_t at = kHeaderSize;
  for (int chunk = 0; at < content.size(); ++chunk) {
    if (content.size() - at < kChunkHeaderSize) fail("chunk " + std::to_string(chunk) + " ends inside its header");
    const std::uint64_t length = le32(content, at);
    const std::uint32_t type = le32(content, at + 4);
    at += kChunkHeaderSize;
    if (length > content.size() - at) {
      fail("chunk " + std::to_string(chunk) + " declares " + std::to_string(length) + " bytes but only " +
           std::to_string(content.size() - at) + " follow (truncated?)");
    }
    const std::string_view data = content.substr(at, static_cast<std::size_t>(length));
    at += static_cast<std::size_t>(length);
    if (chunk == 0) {
      if (type != kJsonChunk) fail("the first chunk is not JSON");
      container.json = data;
      have_json = true;
    } else if (chunk == 1 && type == kBinChunk) {
      container.bin = data;
    }
    // Other chunk types are to be skipped, as the container format asks.
  }
  if (!have_json) fail("it has no JSON chunk");
  return container;
}

}  // namespace toond::scene
