#include "bundle_paths/model_formats.h"

#include <array>

#include "bundle_paths/name_index.h"

namespace toond::bundle_paths {
namespace {

constexpr std::array<std::string_view, 7> kOwn = {".obj", ".m", ".gltf", ".glb", ".stl", ".ply", ".iqm"};

// .md5anim and .bvh hold clips alone: read beside the model they animate.
constexpr std::array<std::string_view, 42> kAssimp = {
    ".fbx",  ".dae",  ".zae", ".3ds", ".3mf",     ".off",     ".x",   ".x3d", ".x3db", ".ase",    ".ask",
    ".ac",   ".ac3d", ".acc", ".amf", ".b3d",     ".cob",     ".dxf", ".hmp", ".ifc",  ".ifczip", ".irrmesh",
    ".lwo",  ".lxo",  ".md2", ".md3", ".md5mesh", ".md5anim", ".mdc", ".mdl", ".ms3d", ".ndo",    ".nff",
    ".enff", ".ogex", ".pmx", ".q3o", ".q3s",     ".sib",     ".smd", ".xgl", ".bvh"};

}  // namespace

std::span<const std::string_view> own_model_extensions() { return kOwn; }
std::span<const std::string_view> assimp_model_extensions() { return kAssimp; }

bool has_any_extension(std::string_view path, std::span<const std::string_view> extensions) {
  for (const std::string_view extension : extensions) {
    if (path.size() >= extension.size() && same_ignoring_case(path.substr(path.size() - extension.size()), extension)) {
      return true;
    }
  }
  return false;
}

bool is_model_file(std::string_view path) { return has_any_extension(path, kOwn) || has_any_extension(path, kAssimp); }

}  // namespace toond::bundle_paths
