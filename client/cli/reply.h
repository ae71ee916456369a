#pragma once
// Turning the daemon's answers into lines for people, kept free of network
// code so the wording can be tested.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace toond::cli {

// "error 400 invalid_parameter at /outline/width: width must be <= 64" from
// a toond error body {"error":{"code","message","path"}}; for a body of any
// other shape (a proxy's HTML page, say) its first line stands in for the
// message. A Retry-After value is appended as advice.
std::string describe_error_reply(int status, std::string_view body, std::string_view retry_after);

// Width and height from a PNG's IHDR chunk; nullopt when `png` is no PNG.
std::optional<std::pair<std::uint32_t, std::uint32_t>> png_size(std::string_view png);

// A content type for a bundle part, from the file name's extension. The
// daemon goes by the part's filename; this only keeps proxies and logs tidy.
std::string content_type_for(std::string_view file_name);

// "1.2 MB", "640 KB", "12 bytes".
std::string human_bytes(std::uint64_t bytes);

}  // namespace toond::cli
