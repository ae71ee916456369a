#pragma once
// Paths inside a bundle: relative, '/'-separated, confined to the bundle.
// The daemon stores files under these names and resolves the references an
// OBJ, MTL or glTF file makes with them; `toon` resolves the same references
// on disk with them to decide what to upload.
#include <optional>
#include <string>
#include <string_view>

namespace toond::bundle_paths {

// Why a name or reference gives no bundle path.
enum class Refusal {
  none,
  empty,     // nothing left once '.' and empty segments are dropped
  absolute,  // a root, or a drive letter ("C:x" is drive-relative, still another machine's path)
  outside,   // '..' climbs above the bundle's root
  malformed  // a NUL byte, or longer than file systems store
};

struct Reading {
  std::string path;  // the bundle path; empty unless refusal is none
  Refusal refusal = Refusal::none;
};

// `\` counts as `/`; `.` and empty segments are dropped; `..` is applied to
// the path as written (lexically, never through links).
Reading read_path(std::string_view path);

// read_path's path, or nullopt.
std::optional<std::string> normalize_path(std::string_view path);

// The bundle path `reference` (as an OBJ, MTL or glTF file writes it) names,
// read relative to the folder of bundle file `from`. An absolute reference is
// refused rather than read relative to the folder.
Reading resolve_reference(std::string_view from, std::string_view reference);

// The folder of bundle path `path` ("" at the bundle's root).
std::string_view folder_of(std::string_view path);

// The reference a glTF URI (not a data: URI) makes: URIs are
// percent-encoded, file names are not. A '%' not followed by two hex digits
// stays as written.
std::string uri_reference(std::string_view uri);

// Why `name` cannot be a bundle file's name although it may be a safe path:
// names end up in JSON answers and on disk, so they must be UTF-8 (one stray
// byte would make every later answer about the model unprintable) and hold no
// control characters (a newline in a name would forge log lines).
std::optional<std::string> unprintable_reason(std::string_view name);

}  // namespace toond::bundle_paths
