#pragma once
// A bundle is the set of files a user uploaded for one model, held in memory
// and addressed by relative path. Every lookup is confined to the bundle: no
// name can reach the file system.
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace toond::scene {

class Bundle {
 public:
  // Adds a file. The path is normalised (see normalize_path); throws
  // ImportError (naming the file) when it is not a safe relative path, when
  // it is already present, or when it would be both a file and a folder.
  void add(std::string_view path, std::string content);

  // Resolves `reference` (as written in an OBJ or MTL) relative to the folder
  // of `from` (a bundle path). `\` counts as `/`; when no exact match exists a
  // case-insensitive match is tried. Returns the bundle path, or nullopt when
  // the reference names no file of the bundle or would leave it.
  std::optional<std::string> resolve(std::string_view from, std::string_view reference) const;

  const std::string* find(std::string_view path) const;
  const std::map<std::string, std::string>& files() const { return files_; }
  std::size_t total_bytes() const;
  bool empty() const { return files_.empty(); }

 private:
  std::map<std::string, std::string> files_;
  // ASCII-lowercased path → the path, for resolve's case-insensitive match
  // in one look-up (a scan per reference made many missing textures cost
  // references × files).
  std::map<std::string, std::string> folded_names_;
};

// Normalises a relative path: `\` → `/`, drops `.` segments and empty
// segments, resolves `..` inside the path. Returns nullopt for absolute paths,
// drive letters, NUL bytes, or `..` that would climb above the root.
std::optional<std::string> normalize_path(std::string_view path);

}  // namespace toond::scene
