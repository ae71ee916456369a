#pragma once
// What a file held that its glTF answer does not carry, said in sentences
// the daemon adds to the upload's warnings: cameras and lights (toond
// places its own), joint influences past four per vertex, colour and
// texture-coordinate sets past the first.
#include <cstddef>
#include <string>
#include <vector>

#include <assimp/scene.h>

namespace toond::assimp_convert {

std::vector<std::string> not_carried(const aiScene& scene, std::size_t vertices_over_four_influences);

}  // namespace toond::assimp_convert
