#pragma once
// Formats that say which way is up and how long a unit is are turned into
// toond's frame: Y up, metres. assimp does this itself for COLLADA (its
// <up_axis> and <unit>); FBX's GlobalSettings (UpAxis, FrontAxis, CoordAxis
// with their signs, UnitScaleFactor in centimetres) come through as scene
// metadata and are applied here, above the root node, so meshes, joints and
// clips all move together. 3MF is Z-up by its specification (a build plate's
// frame), which assimp does not turn, so it is turned here. Formats that
// carry neither (3DS, OFF) are left as they are: the upload's `up=z` turns
// a Z-up file.
#include <string>
#include <vector>

#include <assimp/scene.h>

namespace toond::assimp_convert {

// Applies the scene's own axes and unit, if it states them (or its format
// `format`, the file's extension, fixes them), to its root node; returns
// what was done, one sentence each, for the upload's answer.
std::vector<std::string> make_upright_metres(aiScene& scene, const std::string& format);

}  // namespace toond::assimp_convert
