#pragma once
// A bundle is the set of files a user uploaded for one model, held in memory
// and addressed by relative path. Every lookup is confined to the bundle: no
// name can reach the file system.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bundle_paths/name_index.h"

namespace toond::scene {

class Bundle {
 public:
  // Adds a file. The path is normalised (see bundle_paths::read_path); throws
  // ImportError (naming the file) when it is not a safe relative path, when
  // it is already present, or when it would be both a file and a folder.
  void add(std::string_view path, std::string content);

  // The file `reference` (as written in an OBJ, MTL or glTF) names from
  // bundle file `from`, by bundle_paths::resolve_reference and NameIndex's
  // case rule: the rule `toon` sends files by. Returns the bundle path, or
  // nullopt when the reference names no file of the bundle or would leave it.
  std::optional<std::string> resolve(std::string_view from, std::string_view reference) const;

  // The paths whose file name (folders left out) is `name`, and whose file
  // name less its last extension is `stem`, ignoring ASCII case, in path
  // order: how games find a texture by name (image_lookup.h), one look-up
  // per reference however many files the bundle holds.
  const std::vector<std::string>& paths_named(std::string_view name) const;
  const std::vector<std::string>& paths_with_stem(std::string_view stem) const;

  const std::string* find(std::string_view path) const;
  const std::map<std::string, std::string>& files() const { return files_; }
  std::size_t total_bytes() const;
  bool empty() const { return files_.empty(); }

 private:
  std::map<std::string, std::string> files_;
  bundle_paths::NameIndex names_;
  std::map<std::string, std::vector<std::string>, std::less<>> by_file_name_;  // folded file name → paths
  std::map<std::string, std::vector<std::string>, std::less<>> by_stem_;       // folded stem → paths
};

// `bundle` with file `path`'s bytes replaced by `content` (a converted
// model file read under its own name, so messages name the file uploaded).
Bundle with_file(const Bundle& bundle, const std::string& path, std::string content);

}  // namespace toond::scene
