#pragma once
// Finding the files of an OBJ bundle on disk: the OBJ, the MTL files its
// `mtllib` lines name, and the textures those MTL files reference. Names are
// read and resolved by the daemon's own rules (bundle_paths), so what is
// sent here is what it will look for. Nothing outside the OBJ's folder is
// ever read.
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
// A .gltf brings the .bin and image files its URIs name; a .glb, .stl or
// .ply travels alone; an FBX, COLLADA or other file read through assimp
// brings the images it names (bundle_paths/model_formats.h), found as the
// daemon finds them: as written, else by file name beside the model. A
// folder sends each of its model files with the files it names (the daemon
// tells a model from files holding its clips alone) and every image and
// Quake .skin file beside them, which game models often leave unnamed; a
// folder with no model file is a UsageError.
BundleScan scan_obj_bundle(const std::filesystem::path& obj_path);

// Whether a file name ends in .gltf or .glb (any case).
bool is_gltf_name(std::string_view name);

// Whether `keyword` (any case) is a texture statement whose file is sent.
bool is_texture_keyword(std::string_view keyword);

}  // namespace toond::cli
