#pragma once
#include <optional>
#include <string>

#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// Imports the glTF 2.0 model in bundle file `path` (a .gltf JSON document
// with its .bin and image files in the bundle, or a binary .glb) into a
// Model. What is read:
// - the meshes of scene `scene` (default: the file's default scene, else its
//   first), each node's transform (matrix or translation/rotation/scale)
//   applied in double precision;
// - triangle, strip and fan primitives, indexed or not; POSITION, NORMAL
//   (missing normals are computed as for OBJ), one TEXCOORD set (the one the
//   base colour texture names) and COLOR_0 (linear, stored sRGB-encoded like
//   OBJ's vertex colours); positions that coincide are merged, as an OBJ
//   lists each position once;
// - materials: baseColorFactor and baseColorTexture become the base colour,
//   normalTexture the normal map; emissiveFactor is added to the base colour
//   (clamped to 1), the approximation a toon shade without glow allows;
// - extensions: KHR_mesh_quantization, KHR_texture_transform (of the base
//   colour texture), EXT_texture_webp, KHR_materials_unlit,
//   EXT_meshopt_compression (gltf_meshopt.h) and KHR_draco_mesh_compression
//   (gltf_draco.h; decoded in a helper process, draco_decoder.h).
// What is not read (animations, skins, morph targets, cameras, lights,
// metallic-roughness and occlusion, BLEND, points and lines) is named in
// Model::warnings. An extension in extensionsRequired that is not
// read is an ImportError naming it, checked before anything else is read.
// Every URI must name a file of the bundle or be a data: URI; one that would
// leave the bundle (a scheme such as http:, an absolute path, `..` above the
// bundle's root) is an ImportError. Accessor counts are checked against
// `limits` before anything is allocated from them, and every accessor,
// buffer view and sparse part against the bytes it reads.
// Callers that take any model file use import_bundle (bundle_import.h).
// `choices.gltf_scene` picks the scene (none: the file's default, or its
// first); `choices.z_up()` turns the model. A primitive without NORMAL is
// flat-shaded, as the specification says, whatever `choices.smooth_angle`.
//
// A glTF file that toond-assimp-convert wrote from another format
// (assimp_import.h) is read with `origin` Converted, which keeps what the
// original file meant: a primitive without NORMAL gets normals by angle
// (`choices.smooth_angle`) as any file without normals; an image URI is the
// path the original file gave (often the artist's absolute or Windows path),
// found in the bundle relative to the file or else by its file name alone,
// with a warning; and the glTF extensions the converter chose to write are
// not reported (the converter reports what the original held and the
// answer does not carry).
enum class GltfOrigin { File, Converted };

Model import_gltf_bundle(const Bundle& bundle, const std::string& path, const ImportLimits& limits = {},
                         const ImportChoices& choices = {}, GltfOrigin origin = GltfOrigin::File);

}  // namespace toond::scene
