#pragma once
// Where a format's materials mean something other than what assimp keeps,
// so that its glTF answer (whose colours are linear, and multiply their
// textures) draws the file as the tools that write it do.
#include <assimp/scene.h>

namespace toond::assimp_convert {

// FBX: a texture connected to a material's DiffuseColor takes the colour's
// place (Maya, 3ds Max and Blender draw the texture as it is), while assimp
// keeps the colour beside the texture and its glTF writer multiplies the
// two: Blender's default 0.8 grey would darken every textured FBX by a
// fifth. Makes the colour white where a texture replaces it.
void let_textures_replace_colours(aiScene& scene);

// 3MF: a base material's displaycolor is sRGB (#RRGGBB), which assimp
// keeps as the bytes over 255; glTF's base colour is linear. Decodes them.
void linearise_display_colours(aiScene& scene);

// MD3: assimp names a surface's material "MD3_[skin][surface]"; the
// surface's own name is what a Quake `.skin` file and a request name it by.
void name_md3_materials_by_surface(aiScene& scene);

}  // namespace toond::assimp_convert
