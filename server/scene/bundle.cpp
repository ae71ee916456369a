#include "scene/bundle.h"

#include <algorithm>
#include <vector>

#include "scene/import_error.h"

namespace toond::scene {
namespace {

// Longer names cannot be stored by common file systems, and the store writes
// bundle paths to disk as they are.
constexpr std::size_t kMaxSegment = 255;
constexpr std::size_t kMaxPath = 1024;

char ascii_lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

std::string ascii_folded(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), ascii_lower);
  return out;
}

// After '\\' has become '/': a root or a drive letter ("C:x" is
// drive-relative on Windows, still another machine's path).
bool is_absolute(std::string_view p) {
  if (!p.empty() && p.front() == '/') return true;
  return p.size() >= 2 && p[1] == ':' && ((p[0] >= 'A' && p[0] <= 'Z') || (p[0] >= 'a' && p[0] <= 'z'));
}

// Bundle names end up in JSON answers and on disk: they must be UTF-8 (a
// stray byte would make every later answer about the model unprintable) and
// hold no control characters (a newline in a name would forge log lines).
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

// The name as a message may show it: bytes outside printable ASCII as \xNN.
std::string printable(std::string_view name) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : name.substr(0, 200)) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f) {
      out += ch;
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xf];
    }
  }
  return out;
}

std::string_view folder_of(std::string_view path) {
  const auto slash = path.rfind('/');
  return slash == std::string_view::npos ? std::string_view{} : path.substr(0, slash);
}

}  // namespace

std::optional<std::string> normalize_path(std::string_view path) {
  if (path.empty() || path.size() > kMaxPath) return std::nullopt;
  if (path.find('\0') != std::string_view::npos) return std::nullopt;
  std::string p(path);
  std::replace(p.begin(), p.end(), '\\', '/');
  if (is_absolute(p)) return std::nullopt;

  std::vector<std::string_view> segments;
  std::string_view rest(p);
  while (!rest.empty()) {
    const auto slash = rest.find('/');
    const std::string_view seg = rest.substr(0, slash);
    rest = slash == std::string_view::npos ? std::string_view{} : rest.substr(slash + 1);
    if (seg.empty() || seg == ".") continue;
    if (seg == "..") {
      if (segments.empty()) return std::nullopt;
      segments.pop_back();
      continue;
    }
    if (seg.size() > kMaxSegment) return std::nullopt;
    segments.push_back(seg);
  }
  if (segments.empty()) return std::nullopt;

  std::string out;
  for (const auto seg : segments) {
    if (!out.empty()) out += '/';
    out += seg;
  }
  // "./C:/x" or "a/../C:/x" only becomes a drive path once normalised
  // (found by tests/fuzz/fuzz_multipart).
  if (is_absolute(out)) return std::nullopt;
  return out;
}

void Bundle::add(std::string_view path, std::string content) {
  auto normal = normalize_path(path);
  // The raw name may hold a NUL or worse; keep the reported name printable.
  const std::string shown = printable(path);
  if (const auto reason = unprintable_reason(path)) {
    throw ImportError(shown, "file name '" + shown + "' is not a safe relative path inside the bundle: it holds " +
                                 *reason + "; names must be printable UTF-8");
  }
  if (!normal) {
    throw ImportError(shown, "file name '" + shown +
                                 "' is not a safe relative path inside the bundle "
                                 "(absolute, drive letter, '..' above the root, NUL byte or empty)");
  }
  const std::string& name = *normal;
  if (files_.count(name) != 0) {
    throw ImportError(name, "file '" + name + "' appears twice in the bundle");
  }
  // A path cannot be both a file and a folder once the store writes it out.
  for (std::string_view parent = folder_of(name); !parent.empty(); parent = folder_of(parent)) {
    if (files_.count(std::string(parent)) != 0) {
      throw ImportError(name, "file '" + name + "' would lie inside file '" + std::string(parent) + "'");
    }
  }
  const std::string as_folder = name + '/';
  const auto next = files_.lower_bound(as_folder);
  if (next != files_.end() && next->first.compare(0, as_folder.size(), as_folder) == 0) {
    throw ImportError(name, "file '" + name + "' is also a folder holding '" + next->first + "'");
  }
  files_.emplace(name, std::move(content));
  // Of names that differ only in case, the first in path order answers.
  const auto [folded, added] = folded_names_.emplace(ascii_folded(name), name);
  if (!added && name < folded->second) folded->second = name;
}

std::optional<std::string> Bundle::resolve(std::string_view from, std::string_view reference) const {
  if (reference.empty()) return std::nullopt;
  std::string ref(reference);
  std::replace(ref.begin(), ref.end(), '\\', '/');
  // An absolute reference must not be reinterpreted relative to the folder.
  if (is_absolute(ref) || ref.find('\0') != std::string::npos) return std::nullopt;
  const std::string_view folder = folder_of(from);
  const auto normal = normalize_path(folder.empty() ? ref : std::string(folder) + '/' + ref);
  if (!normal) return std::nullopt;
  if (files_.count(*normal) != 0) return *normal;
  const auto folded = folded_names_.find(ascii_folded(*normal));
  if (folded != folded_names_.end()) return folded->second;
  return std::nullopt;
}

const std::string* Bundle::find(std::string_view path) const {
  const auto it = files_.find(std::string(path));
  return it == files_.end() ? nullptr : &it->second;
}

std::size_t Bundle::total_bytes() const {
  std::size_t total = 0;
  for (const auto& [name, content] : files_) total += content.size();
  return total;
}

}  // namespace toond::scene
