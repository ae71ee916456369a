#pragma once
// The formats toond reads through assimp (FBX, COLLADA, 3DS, 3MF, OFF and
// the others below), converted in the helper program toond-assimp-convert
// (server/helpers/assimp_convert/) with limits on time, memory and output, and then
// read as any glTF upload is (gltf_import.h, GltfOrigin::Converted): the
// glTF importer's checks are the answer's validation, and skins, morph
// targets and clips take the same path as a glTF character's. A crash, a
// hang or a refusal of the helper is an ImportError naming the file; the
// daemon does not link assimp.
#include <chrono>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// Whether bundle path `path` has one of the extensions read through the
// helper (bundle_paths::assimp_model_extensions()).
bool read_through_assimp(std::string_view path);

// How long one conversion may take unless the import's own deadline is
// nearer.
inline constexpr std::chrono::milliseconds kAssimpTimeLimit{30000};

// The helper program: $TOOND_ASSIMP_CONVERTER when set, else
// toond-assimp-convert beside the running executable.
std::filesystem::path assimp_converter_program();

// What the helper made of one file: a binary glTF, and its notes (standard
// error: "note: ..." and "frame_rate: CLIP FPS" lines).
struct ConvertedFile {
  std::string glb;
  std::string notes;
};

// Converts bundle file `path` (one of assimp_extensions()) in the helper.
// Throws ImportError naming the file when the helper fails or answers
// something other than glTF.
ConvertedFile convert_with_assimp(const Bundle& bundle, const std::string& path, const ImportLimits& limits = {});

// The helper's notes about `path` as warnings of `model`, and its clips'
// frame rates: `clips` lists, for each of the model's clips from index
// `first_clip` on, its index in the converted file (the model's own clips:
// 0, 1, ...).
void add_converter_notes(const ConvertedFile& converted, const std::string& path, Model& model, std::size_t first_clip,
                         const std::vector<std::size_t>& clips);

// Imports bundle file `path` (one of assimp_extensions()) with the rest of
// the bundle as its textures. What the helper reports the file held but the
// model does not (cameras, lights, influences past four per vertex) and how
// it turned the file upright and into metres are in Model::warnings.
Model import_assimp_bundle(const Bundle& bundle, const std::string& path, const ImportLimits& limits = {},
                           const ImportChoices& choices = {});

}  // namespace toond::scene
