#pragma once
// Reading one model file with assimp from bytes in memory, with every other
// file out of its reach: a COLLADA or FBX file names textures and other
// files by path, and assimp's own file system would open any of them (the
// daemon finds textures in the upload itself).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <assimp/scene.h>
#include <assimp/Importer.hpp>

namespace toond::assimp_convert {

// The scene `bytes` hold, read as the format its extension `format` names
// ("fbx", "dae"), triangulated and checked by assimp's validation step.
// A scene refused only for its clips' timing (animation_timing.h) is read
// again, mended and checked, with a sentence in `notes` for each mend.
// Throws std::runtime_error with assimp's reason.
const aiScene& read_scene(Assimp::Importer& importer, std::string_view bytes, const std::string& format,
                          std::vector<std::string>& notes);

// Keeps the four strongest joint influences of every vertex, renormalised:
// the glTF answer carries four per vertex. Returns how many vertices had
// more.
std::size_t keep_four_influences(Assimp::Importer& importer);

}  // namespace toond::assimp_convert
