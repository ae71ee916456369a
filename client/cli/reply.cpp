#include "reply.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "text/trim.h"

namespace toond::cli {

std::string describe_error_reply(int status, std::string_view body, std::string_view retry_after) {
  std::string out = "error " + std::to_string(status);
  const nlohmann::json doc = nlohmann::json::parse(body, nullptr, false);
  const nlohmann::json* error = nullptr;
  if (doc.is_object()) {
    if (auto it = doc.find("error"); it != doc.end() && it->is_object()) error = &*it;
  }
  auto text = [](const nlohmann::json& obj, const char* key) -> std::string {
    auto it = obj.find(key);
    if (it == obj.end() || it->is_null()) return {};
    return it->is_string() ? it->get<std::string>() : it->dump();
  };
  if (error) {
    if (std::string code = text(*error, "code"); !code.empty()) out += " " + code;
    if (std::string path = text(*error, "path"); !path.empty()) out += " at " + path;
    const std::string message = text(*error, "message");
    out += ": " + (message.empty() ? std::string("(no message)") : message);
  } else {
    const std::string_view first = text::trim(body.substr(0, body.find('\n')));
    constexpr std::size_t kMax = 200;
    if (first.empty()) {
      out += " (empty answer)";
    } else {
      out += ": " + std::string(first.substr(0, kMax)) + (first.size() > kMax ? "..." : "");
    }
  }
  if (!retry_after.empty()) out += " (busy; retry after " + std::string(retry_after) + " s)";
  return out;
}

std::optional<std::pair<std::uint32_t, std::uint32_t>> png_size(std::string_view png) {
  // 8-byte signature, then the IHDR chunk: length, "IHDR", width, height.
  static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  if (png.size() < 24 || png.substr(0, 8) != kSignature || png.substr(12, 4) != "IHDR") {
    return std::nullopt;
  }
  auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(png[at + i]);
    return v;
  };
  return std::make_pair(be32(16), be32(20));
}

std::string content_type_for(std::string_view file_name) {
  std::string ext;
  if (auto dot = file_name.rfind('.'); dot != std::string_view::npos) {
    ext = std::string(file_name.substr(dot + 1));
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  }
  if (ext == "obj" || ext == "mtl") return "text/plain";
  if (ext == "png") return "image/png";
  if (ext == "jpg" || ext == "jpeg") return "image/jpeg";
  if (ext == "tga") return "image/x-tga";
  if (ext == "bmp") return "image/bmp";
  return "application/octet-stream";
}

std::string human_bytes(std::uint64_t bytes) {
  char buf[32];
  if (bytes >= 1000000u) {
    std::snprintf(buf, sizeof buf, "%.1f MB", static_cast<double>(bytes) / 1e6);
  } else if (bytes >= 1000u) {
    std::snprintf(buf, sizeof buf, "%.0f KB", static_cast<double>(bytes) / 1e3);
  } else {
    std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(bytes));
  }
  return buf;
}

}  // namespace toond::cli
