#include "bundle_paths/name_index.h"

#include <algorithm>

namespace toond::bundle_paths {

namespace {

char folded(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

std::string case_folded(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), folded);
  return out;
}

bool same_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return folded(x) == folded(y); });
}

void NameIndex::add(const std::string& name) {
  names_.insert(name);
  const auto [folded, added] = folded_.emplace(case_folded(name), name);
  if (!added && name < folded->second) folded->second = name;
}

std::optional<std::string> NameIndex::find(std::string_view name) const {
  if (const auto it = names_.find(name); it != names_.end()) return *it;
  if (const auto it = folded_.find(case_folded(name)); it != folded_.end()) return it->second;
  return std::nullopt;
}

}  // namespace toond::bundle_paths
