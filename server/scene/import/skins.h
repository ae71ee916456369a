#pragma once
// A model's materials as its game draws them, settled once the model file
// is read: the images an upload puts on them (`?textures`, as a game sets
// a model's skins from its code), the one image of an upload whose model
// file leaves its skin to the game, the drawing conventions of the engine a
// format comes from where the file says nothing, and the images left over.
// docs/formats.md, "Game files", says the same for users.
#include <string>
#include <string_view>

#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// What an image's alpha says where nothing else does: opaque without
// alpha; a cut-out where some texels are wholly transparent (sprites,
// fences, a hat layer); blended where every texel shows a little (glass).
AlphaMode alpha_of_image(const Texture& image);

// Whether the materials of model file `path` leave their images to the
// game's code: the formats of game engines read through assimp (B3D, MD2,
// MD3, MD5, X, ...) and IQM, and an OBJ uploaded without any MTL.
bool skins_left_to_game(const Bundle& bundle, std::string_view path);

// Puts an MD3's `.skin` file's images on its surfaces' materials, then
// `choices.textures` on `model`'s materials (in material order, or
// "material:image" by name), then, where the file leaves skins to the game
// and no material has a colour texture, the upload's one unused image on
// every material. A material given an image by the upload shows it as it
// is (white base colour). Throws ImportError at "?textures" for an image
// not in the bundle or not decodable, a material name the model lacks, or
// more images than materials.
void put_skins(Model& model, const Bundle& bundle, const std::string& path, const ImportChoices& choices,
               const ImportLimits& limits);

// The conventions of the engine model file `path`'s format comes from, for
// what its files do not say: an OBJ's colour image with alpha is drawn as
// alpha_of_image says (Minetest's and most games' props); B3D, MD2, MD3,
// IQM and MD5 files carry no highlight (matte); Irrlicht (Minetest) alpha-tests B3D textures
// at 0.5 and ignores brush colours where a texture is set; Quake draws
// MD2 and MD3 skins opaque (their alpha feeds shader effects); Cube 2
// alpha-tests IQM and MD5 skins at 0.9.
void apply_format_conventions(Model& model, std::string_view path);

// A warning for each image of the bundle that no material uses, saying how
// to put it on one.
void warn_unused_images(Model& model, const Bundle& bundle);

}  // namespace toond::scene
