#pragma once
// Inter-Quake Model (.iqm, version 2, the format of Cube 2: Sauerbraten,
// Tesseract and others): meshes, a skeleton and clips, read into a binary
// glTF that the glTF importer then reads as it reads a converted file
// (GltfOrigin::Converted: its checks, its rig and clip handling, textures
// found as games find them). assimp's IQM reader reads neither skeletons
// nor clips, and crashes on a file holding clips alone.
//
// As the format's exporters write it: Z up (the upload's `up` defaults to
// z for .iqm), texture coordinates from the image's top row, triangles
// wound clockwise (turned here). Each IQM mesh is a material named after
// the mesh (Sauerbraten's `iqmskin` names them so), its texture the mesh's
// material string (often an author's absolute path: found by file name).
// Clips come from the model file and from the upload's IQM files holding
// clips alone (Sauerbraten's `iqmanim`): their poses go onto the model's
// joints by name where the file names its joints, else in order, when the
// skeletons agree (count and parents); otherwise the clip is left out with
// a warning saying why.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// What an IQM file holds, from its header: nullopt when `bytes` is not an
// IQM version 2 file.
struct IqmContents {
  std::size_t meshes = 0;
  std::size_t joints = 0;
  std::size_t poses = 0;
  std::size_t clips = 0;
  std::vector<std::string> clip_names;
};
std::optional<IqmContents> iqm_contents(std::string_view bytes);

// Imports IQM file `path` of `bundle`, with the clips of `clip_files`
// (other IQM files of the bundle holding clips alone). Throws ImportError
// naming the file when one is malformed.
// The binary glTF import_iqm_bundle reads: the model of IQM file `path`
// with the clips of `clip_files`; warnings for clips left out go to
// `warnings`, each clip's frames a second (in order) to `rates`.
std::string iqm_glb(const Bundle& bundle, const std::string& path, const std::vector<std::string>& clip_files,
                    std::vector<std::string>& warnings, std::vector<double>& rates, const ImportLimits& limits = {});

Model import_iqm_bundle(const Bundle& bundle, const std::string& path, const std::vector<std::string>& clip_files,
                        const ImportLimits& limits = {}, const ImportChoices& choices = {});

}  // namespace toond::scene
