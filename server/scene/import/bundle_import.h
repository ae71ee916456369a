#pragma once
// The one entry point for turning an uploaded bundle into a Model, whatever
// its model file's format.
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// Imports the bundle's one model file with the importer its extension
// (ASCII case-insensitive) names: .obj (import_obj_bundle, obj_import.h),
// .m (import_m_bundle, m_import.h), .gltf / .glb (import_gltf_bundle,
// gltf_import.h), .stl and .ply (stl_import.h, ply_import.h), or one of
// the formats read through assimp (import_assimp_bundle, assimp_import.h). A glTF file is also known by its content
// (gltf_container.h) whatever its name, when it is the bundle's only model file. Throws ImportError naming the files
// when the bundle holds no model file or more than one, and whatever the importer throws. The mesh comes back with its
// levels of detail and in vertex-cache order (prepare_levels_of_detail, mesh_lod.h). `limits` bound what an upload may
// make (ImportLimitError beyond). `choices.gltf_scene` picks a glTF file's scene (ImportError when the model file is
// not glTF, or has no such scene); `choices.up` left to the format is settled by with_format_up.
Model import_bundle(const Bundle& bundle, const ImportLimits& limits = {}, const ImportChoices& choices = {});

// Whether the format of model file `path` is Z-up by its tools' convention:
// STL and PLY (CAD, 3D printing, scanners, Blender's own export), 3MF and
// AMF (a build plate's frame, by their specifications). The rest are Y-up
// (OBJ, glTF) or say which axis is up themselves (FBX, COLLADA).
bool z_up_by_convention(std::string_view path);

// `choices` with an up axis left to the format (ImportChoices::Up::
// FormatDefault) settled as the bundle's model file's convention. Throws
// ImportError as import_bundle does when the bundle holds no model file or
// more than one.
ImportChoices with_format_up(const Bundle& bundle, ImportChoices choices);

// Whether `path` ends in `extension` (".obj"), ASCII case-insensitive.
bool has_extension(std::string_view path, std::string_view extension);

// The path of the bundle's one file ending in any of `extensions`. Throws
// ImportError naming the files when there is none (file: "") or more than
// one (file: the second); `noun` is how messages name such a file (".obj",
// ".obj or .m").
std::string find_model_file(const Bundle& bundle, std::initializer_list<std::string_view> extensions,
                            std::string_view noun);
std::string find_model_file(const Bundle& bundle, std::span<const std::string_view> extensions, std::string_view noun);
// The same among `paths` only (of `bundle`, which messages list when none fits).
std::string find_model_file_among(const Bundle& bundle, const std::vector<std::string>& paths,
                                  std::span<const std::string_view> extensions, std::string_view noun);

}  // namespace toond::scene
