#pragma once
// Formats that say which way is up and how long a unit is are turned into
// toond's frame: Y up, metres. assimp does this itself for COLLADA (its
// <up_axis> and <unit>); FBX's GlobalSettings (UpAxis, FrontAxis, CoordAxis
// with their signs, UnitScaleFactor in centimetres) come through as scene
// metadata and are applied here, above the root node, so meshes, joints and
// clips all move together. Formats that carry neither (3DS, OFF, and 3MF
// and AMF, Z-up by their specifications) are left as they are: the
// daemon turns a Z-up file by the upload's `up`, whose default is the
// format's convention (scene/import/bundle_import.h).
#include <string>
#include <vector>

#include <assimp/scene.h>

namespace toond::assimp_convert {

// Applies the scene's own axes and unit, if it states them, to its root
// node; returns what was done, one sentence each, for the upload's answer.
std::vector<std::string> make_upright_metres(aiScene& scene);

}  // namespace toond::assimp_convert
