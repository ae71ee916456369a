#include "glb/glb_container.h"

#include <cstdint>

namespace toond::glb {
namespace {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

void append_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

std::uint32_t u32_at(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
  return v;
}

}  // namespace

std::string glb_container(std::string_view json_text, std::string_view bin) {
  std::string json_chunk(json_text);
  while (json_chunk.size() % 4) json_chunk.push_back(' ');
  std::string bin_chunk(bin);
  while (bin_chunk.size() % 4) bin_chunk.push_back('\0');
  const std::size_t bin_bytes = bin_chunk.empty() ? 0 : 8 + bin_chunk.size();
  std::string glb;
  append_u32(glb, kMagic);
  append_u32(glb, 2);
  append_u32(glb, static_cast<std::uint32_t>(12 + 8 + json_chunk.size() + bin_bytes));
  append_u32(glb, static_cast<std::uint32_t>(json_chunk.size()));
  append_u32(glb, kJsonChunk);
  glb += json_chunk;
  if (bin_chunk.empty()) return glb;  // the binary chunk is optional
  append_u32(glb, static_cast<std::uint32_t>(bin_chunk.size()));
  append_u32(glb, kBinChunk);
  glb += bin_chunk;
  return glb;
}

std::optional<GlbChunks> glb_chunks(std::string_view bytes) {
  if (bytes.size() < 20 || u32_at(bytes, 0) != kMagic || u32_at(bytes, 4) != 2) return std::nullopt;
  if (u32_at(bytes, 8) > bytes.size()) return std::nullopt;
  bytes = bytes.substr(0, u32_at(bytes, 8));
  GlbChunks chunks;
  std::size_t at = 12;
  for (int chunk = 0; at + 8 <= bytes.size(); ++chunk) {
    const std::size_t length = u32_at(bytes, at);
    const std::uint32_t type = u32_at(bytes, at + 4);
    at += 8;
    if (length > bytes.size() - at) return std::nullopt;
    const std::string_view data = bytes.substr(at, length);
    at += length;
    if (chunk == 0 && type != kJsonChunk) return std::nullopt;
    if (chunk == 0) chunks.json = data;
    if (chunk == 1 && type == kBinChunk) chunks.bin = data;
  }
  if (chunks.json.empty()) return std::nullopt;
  return chunks;
}

}  // namespace toond::glb
