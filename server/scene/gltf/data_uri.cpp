#include "scene/gltf/data_uri.h"

#include <openssl/evp.h>

#include <climits>

namespace toond::scene {
namespace {

bool starts_with_ascii_nocase(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    const char c = (s[i] >= 'A' && s[i] <= 'Z') ? static_cast<char>(s[i] - 'A' + 'a') : s[i];
    if (c != prefix[i]) return false;
  }
  return true;
}

}  // namespace

bool is_data_uri(std::string_view uri) { return starts_with_ascii_nocase(uri, "data:"); }

std::optional<DataUri> decode_data_uri(std::string_view uri) {
  if (!is_data_uri(uri)) return std::nullopt;
  const auto comma = uri.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  const std::string_view header = uri.substr(5, comma - 5);
  if (header.size() < 7 || !starts_with_ascii_nocase(header.substr(header.size() - 7), ";base64")) return std::nullopt;
  DataUri result;
  result.media_type = std::string(header.substr(0, header.find(';')));

  std::string payload;
  payload.reserve(uri.size() - comma);
  for (const char c : uri.substr(comma + 1)) {
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n') payload.push_back(c);
  }
  // Unpadded base64 is common in hand-written files; pad it.
  if (payload.size() % 4 == 1) return std::nullopt;
  while (payload.size() % 4 != 0) payload.push_back('=');
  if (payload.size() > static_cast<std::size_t>(INT_MAX)) return std::nullopt;
  std::size_t padding = 0;
  for (std::size_t i = payload.size(); i > 0 && payload[i - 1] == '=' && padding < 2; --i) ++padding;
  result.bytes.resize(payload.size() / 4 * 3);
  const int written = EVP_DecodeBlock(result.bytes.data(), reinterpret_cast<const unsigned char*>(payload.data()),
                                      static_cast<int>(payload.size()));
  if (written < 0 || static_cast<std::size_t>(written) < padding) return std::nullopt;
  // EVP_DecodeBlock counts the padding as zero bytes.
  result.bytes.resize(static_cast<std::size_t>(written) - padding);
  return result;
}

}  // namespace toond::scene
