#include "bundle_paths/bundle_path.h"

#include <algorithm>
#include <vector>

namespace toond::bundle_paths {
namespace {

// Longer names cannot be stored by common file systems, and the daemon's
// store writes bundle paths to disk as they are.
constexpr std::size_t kMaxSegment = 255;
constexpr std::size_t kMaxPath = 1024;

// After '\\' has become '/'.
bool is_absolute(std::string_view p) {
  if (!p.empty() && p.front() == '/') return true;
  return p.size() >= 2 && p[1] == ':' && ((p[0] >= 'A' && p[0] <= 'Z') || (p[0] >= 'a' && p[0] <= 'z'));
}

Reading refused(Refusal why) { return {{}, why}; }

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string_view folder_of(std::string_view path) {
  const auto slash = path.rfind('/');
  return slash == std::string_view::npos ? std::string_view{} : path.substr(0, slash);
}

std::string uri_reference(std::string_view uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex_digit(uri[i + 1]) >= 0 && hex_digit(uri[i + 2]) >= 0) {
      out.push_back(static_cast<char>(hex_digit(uri[i + 1]) * 16 + hex_digit(uri[i + 2])));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

Reading read_path(std::string_view path) {
  if (path.empty()) return refused(Refusal::empty);
  if (path.size() > kMaxPath || path.find('\0') != std::string_view::npos) return refused(Refusal::malformed);
  std::string p(path);
  std::replace(p.begin(), p.end(), '\\', '/');
  if (is_absolute(p)) return refused(Refusal::absolute);

  std::vector<std::string_view> segments;
  std::string_view rest(p);
  while (!rest.empty()) {
    const auto slash = rest.find('/');
    const std::string_view seg = rest.substr(0, slash);
    rest = slash == std::string_view::npos ? std::string_view{} : rest.substr(slash + 1);
    if (seg.empty() || seg == ".") continue;
    if (seg == "..") {
      if (segments.empty()) return refused(Refusal::outside);
      segments.pop_back();
      continue;
    }
    if (seg.size() > kMaxSegment) return refused(Refusal::malformed);
    segments.push_back(seg);
  }
  if (segments.empty()) return refused(Refusal::empty);

  std::string out;
  for (const auto seg : segments) {
    if (!out.empty()) out += '/';
    out += seg;
  }
  // "./C:/x" or "a/../C:/x" only becomes a drive path once normalised
  // (found by tests/fuzz/fuzz_multipart).
  if (is_absolute(out)) return refused(Refusal::absolute);
  return {std::move(out), Refusal::none};
}

std::optional<std::string> normalize_path(std::string_view path) {
  Reading r = read_path(path);
  if (r.refusal != Refusal::none) return std::nullopt;
  return std::move(r.path);
}

Reading resolve_reference(std::string_view from, std::string_view reference) {
  if (reference.empty()) return refused(Refusal::empty);
  std::string ref(reference);
  std::replace(ref.begin(), ref.end(), '\\', '/');
  if (is_absolute(ref)) return refused(Refusal::absolute);
  const std::string_view folder = folder_of(from);
  return read_path(folder.empty() ? ref : std::string(folder) + '/' + ref);
}

std::optional<std::string> unprintable_reason(std::string_view name) {
  for (std::size_t i = 0; i < name.size();) {
    const auto c = static_cast<unsigned char>(name[i]);
    if (c < 0x20 || c == 0x7f) return "a control character";
    std::size_t extra = 0;
    if (c < 0x80) {
      extra = 0;
    } else if ((c & 0xe0) == 0xc0 && c >= 0xc2) {
      extra = 1;
    } else if ((c & 0xf0) == 0xe0) {
      extra = 2;
    } else if ((c & 0xf8) == 0xf0 && c <= 0xf4) {
      extra = 3;
    } else {
      return "bytes that are not UTF-8";
    }
    if (i + extra >= name.size()) {
      return "bytes that are not UTF-8";
    }
    for (std::size_t k = 1; k <= extra; ++k) {
      if ((static_cast<unsigned char>(name[i + k]) & 0xc0) != 0x80) return "bytes that are not UTF-8";
    }
    i += extra + 1;
  }
  return std::nullopt;
}

}  // namespace toond::bundle_paths
