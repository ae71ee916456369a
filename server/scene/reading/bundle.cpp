#include "scene/reading/bundle.h"

#include <algorithm>

#include "bundle_paths/bundle_path.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

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

}  // namespace

void Bundle::add(std::string_view path, std::string content) {
  const auto normal = bundle_paths::normalize_path(path);
  // The raw name may hold a NUL or worse; keep the reported name printable.
  const std::string shown = printable(path);
  if (const auto reason = bundle_paths::unprintable_reason(path)) {
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
  for (std::string_view parent = bundle_paths::folder_of(name); !parent.empty();
       parent = bundle_paths::folder_of(parent)) {
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
  names_.add(name);
  const std::string_view file_name = std::string_view(name).substr(name.find_last_of('/') + 1);
  const std::size_t dot = file_name.rfind('.');
  const std::string_view stem = dot == std::string_view::npos || dot == 0 ? file_name : file_name.substr(0, dot);
  // Files are added in any order; the lists stay in path order so a
  // look-up's answer does not depend on it.
  for (const auto& [index, key] : {std::pair{&by_file_name_, file_name}, std::pair{&by_stem_, stem}}) {
    std::vector<std::string>& paths = (*index)[bundle_paths::case_folded(key)];
    paths.insert(std::upper_bound(paths.begin(), paths.end(), name), name);
  }
}

const std::vector<std::string>& Bundle::paths_named(std::string_view name) const {
  static const std::vector<std::string> kNone;
  const auto it = by_file_name_.find(bundle_paths::case_folded(name));
  return it == by_file_name_.end() ? kNone : it->second;
}

const std::vector<std::string>& Bundle::paths_with_stem(std::string_view stem) const {
  static const std::vector<std::string> kNone;
  const auto it = by_stem_.find(bundle_paths::case_folded(stem));
  return it == by_stem_.end() ? kNone : it->second;
}

std::optional<std::string> Bundle::resolve(std::string_view from, std::string_view reference) const {
  const bundle_paths::Reading reading = bundle_paths::resolve_reference(from, reference);
  if (reading.refusal != bundle_paths::Refusal::none) return std::nullopt;
  return names_.find(reading.path);
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

Bundle with_file(const Bundle& bundle, const std::string& path, std::string content) {
  Bundle out;
  for (const auto& [name, bytes] : bundle.files()) {
    if (name != path) out.add(name, bytes);
  }
  out.add(path, std::move(content));
  return out;
}

}  // namespace toond::scene
