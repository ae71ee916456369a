#pragma once
// Which files of a bundle are models, by extension: toond's own readers'
// formats and those read through assimp in the toond-assimp-convert helper.
// `toon` and the daemon take the same list from here; the web page's
// (client/web/upload.js) is checked against it by a test.
#include <span>
#include <string_view>

namespace toond::bundle_paths {

// ".obj", ".m", ".gltf", ".glb", ".stl", ".ply".
std::span<const std::string_view> own_model_extensions();

// The formats read through assimp (".fbx", ".dae", ".3ds", ".3mf", ".off",
// ...). Formats whose models span several files (Unreal's .3d pairs,
// LightWave scenes, Quake archives), files that hold only motion, and old
// .blend files (assimp reads Blender 2.7x at best; export glTF instead) are
// not among them.
std::span<const std::string_view> assimp_model_extensions();

// Whether `path` ends (ASCII case-insensitively) in one of `extensions`.
bool has_any_extension(std::string_view path, std::span<const std::string_view> extensions);

// Whether `path` names a model file of either kind.
bool is_model_file(std::string_view path);

// How messages name the formats ("model (.obj, .gltf, ...)").
inline constexpr std::string_view kModelFormatsText =
    ".obj, .gltf, .glb, .stl, .ply, .iqm, .fbx, .dae, .3ds, .3mf, .off, .m or another format assimp reads";

}  // namespace toond::bundle_paths
