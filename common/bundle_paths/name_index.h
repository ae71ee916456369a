#pragma once
// Which file a bundle path names when the spelling differs in case: bundles
// made on Windows or macOS often write references in another case than the
// files have. The exact name wins; otherwise the name equal to it ignoring
// ASCII case, and of several such names the least in byte order, so the
// answer never depends on the order files were added or listed.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace toond::bundle_paths {

// `s` with ASCII letters lowered; other bytes (UTF-8 included) stay.
std::string case_folded(std::string_view s);
bool same_ignoring_case(std::string_view a, std::string_view b);

class NameIndex {
 public:
  void add(const std::string& name);
  std::optional<std::string> find(std::string_view name) const;

 private:
  std::set<std::string, std::less<>> names_;
  // Folded name → the least name that folds to it: one look-up per
  // reference (a scan per reference made many missing textures cost
  // references × files).
  std::map<std::string, std::string, std::less<>> folded_;
};

}  // namespace toond::bundle_paths
