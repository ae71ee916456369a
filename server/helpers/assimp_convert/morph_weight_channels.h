#pragma once
// assimp reads morph-target animation (FBX blend-shape channels, COLLADA
// morph weights) into aiAnimation::mMorphMeshChannels, but its glTF writer
// (5.2) leaves those channels out, so a character's face or a bulging
// muscle would stand still. This adds them to the written glTF as
// "weights" channels of the nodes that draw each mesh, in the clip of the
// same name.
#include <string>
#include <vector>

#include <assimp/scene.h>

namespace toond::assimp_convert {

// `glb` (assimp's answer for `scene`) with the scene's morph-weight
// channels added. A channel the answer cannot take (a mesh drawn with
// targets of different counts, nodes the writer renamed) is left out with a
// sentence in `notes`. Throws std::runtime_error when `glb` is not a
// well-formed container.
std::string with_morph_weight_channels(const std::string& glb, const aiScene& scene, std::vector<std::string>& notes);

}  // namespace toond::assimp_convert
