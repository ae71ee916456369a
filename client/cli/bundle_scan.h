#pragma once
// Finding the files of an OBJ bundle on disk: the OBJ, the MTL files its
// `mtllib` lines name, and the textures those MTL files reference. The
// daemon resolves references the same way (relative to the referring file,
// `\` as `/`, case-insensitive fallback), so what is sent here is what it
// will look for. Nothing outside the OBJ's folder is ever read.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace toond::cli {

struct BundleFile {
  std::string name;  // path inside the bundle: relative to the OBJ's folder, '/'-separated
  std::filesystem::path disk_path;
  std::string content;
};

struct BundleScan {
  std::vector<BundleFile> files;      // the OBJ first, then MTL files, then textures; each once
  std::vector<std::string> warnings;  // missing or refused references, for stderr
};

// Throws UsageError when the OBJ itself cannot be read. Everything else
// (missing MTL or texture, a reference leaving the folder) becomes a warning.
// A .gltf brings the .bin and image files its URIs name; a .glb travels
// alone. A folder stands for its one model file (.obj, .m, .gltf or .glb;
// none or several is a UsageError).
BundleScan scan_obj_bundle(const std::filesystem::path& obj_path);

// Whether a file name ends in .gltf or .glb (any case).
bool is_gltf_name(std::string_view name);

// The parts of an MTL line that name files, exposed for tests.
// Whether `keyword` (any case) is a texture statement whose file is sent.
bool is_texture_keyword(std::string_view keyword);
// File names a `mtllib` line lists (several per line are allowed; `\ `
// escapes a space).
std::vector<std::string> mtllib_names(std::string_view rest_of_line);
// Candidate file names for a texture statement, best first: the options
// (-bm 2, -o 0.1 0.2, -imfchan r, ...) are dropped, and when several words
// remain both "all of them with their spaces" and "the last word" are
// offered, since exporters write unescaped spaces and readers disagree.
std::vector<std::string> texture_name_candidates(std::string_view rest_of_line);

}  // namespace toond::cli
