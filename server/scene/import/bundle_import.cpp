#include "scene/import/bundle_import.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "bundle_paths/model_formats.h"
#include "scene/animation/motion_classes.h"
#include "scene/gltf/gltf_container.h"
#include "scene/gltf/gltf_import.h"
#include "scene/import/assimp_import.h"
#include "scene/import/m_import.h"
#include "scene/import/obj_import.h"
#include "scene/import/ply_import.h"
#include "scene/import/stl_import.h"
#include "scene/mesh/crease_edges.h"
#include "scene/mesh/enclosure.h"
#include "scene/mesh/intersection_lines.h"
#include "scene/mesh/mesh_lod.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

char ascii_lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

std::string single_quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

}  // namespace

bool has_extension(std::string_view path, std::string_view extension) {
  if (path.size() < extension.size()) return false;
  const std::string_view tail = path.substr(path.size() - extension.size());
  for (std::size_t i = 0; i < tail.size(); ++i) {
    if (ascii_lower(tail[i]) != ascii_lower(extension[i])) return false;
  }
  return true;
}

std::string find_model_file(const Bundle& bundle, std::initializer_list<std::string_view> extensions,
                            std::string_view noun) {
  return find_model_file(bundle, std::span<const std::string_view>(extensions.begin(), extensions.size()), noun);
}

std::string find_model_file(const Bundle& bundle, std::span<const std::string_view> extensions, std::string_view noun) {
  std::vector<std::string> found;
  for (const auto& [path, content] : bundle.files()) {
    for (const std::string_view extension : extensions) {
      if (has_extension(path, extension)) {
        found.push_back(path);
        break;
      }
    }
  }
  if (found.size() == 1) return found.front();
  std::string listing;
  if (found.empty()) {
    for (const auto& [path, content] : bundle.files()) listing += (listing.empty() ? "" : ", ") + single_quoted(path);
    throw ImportError("", "the bundle holds no " + std::string(noun) + " file" +
                              (listing.empty() ? std::string(" (it is empty)") : " (it holds " + listing + ")"));
  }
  for (const auto& path : found) listing += (listing.empty() ? "" : ", ") + single_quoted(path);
  throw ImportError(found[1], "the bundle holds " + std::to_string(found.size()) + " " + std::string(noun) +
                                  " files (" + listing + "); a bundle is one model with exactly one " +
                                  std::string(noun) + " file");
}

namespace {

// Every model-file extension import_bundle takes, toond's own readers' first.
std::vector<std::string_view> model_extensions() {
  std::vector<std::string_view> extensions;
  for (const auto& list : {bundle_paths::own_model_extensions(), bundle_paths::assimp_model_extensions()}) {
    extensions.insert(extensions.end(), list.begin(), list.end());
  }
  return extensions;
}

const std::string kModelFileNoun = "model (" + std::string(bundle_paths::kModelFormatsText) + ")";

// The bundle's glTF files, known by content whatever their names (a .bin
// or image never starts like one).
std::vector<std::string> gltf_files(const Bundle& bundle) {
  std::vector<std::string> found;
  for (const auto& [path, content] : bundle.files()) {
    if (!has_extension(path, ".obj") && !has_extension(path, ".mtl") && !has_extension(path, ".m") &&
        looks_like_gltf(content)) {
      found.push_back(path);
    }
  }
  return found;
}

// The file the bundle's model is read from, and whether it is glTF: its
// one glTF file (known by content) when it holds no OBJ or .m, else its one
// model file by extension.
struct ModelFile {
  std::string path;
  bool gltf = false;
};

ModelFile model_file(const Bundle& bundle) {
  const std::vector<std::string> gltf = gltf_files(bundle);
  if (gltf.size() == 1 && !std::any_of(bundle.files().begin(), bundle.files().end(), [](const auto& file) {
        return has_extension(file.first, ".obj") || has_extension(file.first, ".m");
      })) {
    return {gltf.front(), true};
  }
  std::string path = find_model_file(bundle, model_extensions(), kModelFileNoun);
  const bool by_name = has_extension(path, ".gltf") || has_extension(path, ".glb");
  return {std::move(path), by_name};
}

}  // namespace

bool z_up_by_convention(std::string_view path) {
  for (const std::string_view extension : {".stl", ".ply", ".3mf", ".amf"}) {
    if (has_extension(path, extension)) return true;
  }
  return false;
}

ImportChoices with_format_up(const Bundle& bundle, ImportChoices choices) {
  if (choices.up == ImportChoices::Up::FormatDefault) {
    choices.up = z_up_by_convention(model_file(bundle).path) ? ImportChoices::Up::Z : ImportChoices::Up::Y;
  }
  return choices;
}

Model import_bundle(const Bundle& bundle, const ImportLimits& given_limits, const ImportChoices& asked) {
  const ImportChoices choices = with_format_up(bundle, asked);
  ImportLimits limits = given_limits;
  if (limits.max_seconds > 0.0 && limits.deadline == std::chrono::steady_clock::time_point::max()) {
    limits.deadline =
        std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                               std::chrono::duration<double>(limits.max_seconds));
  }
  const ModelFile file = model_file(bundle);
  const std::string& path = file.path;
  if (choices.gltf_scene && !file.gltf) {
    throw ImportError(path, path + ": a scene was asked for, but only glTF files have scenes");
  }
  Model model;
  if (file.gltf) {
    model = import_gltf_bundle(bundle, path, limits, choices);
  } else if (read_through_assimp(path)) {
    model = import_assimp_bundle(bundle, path, limits, choices);
  } else if (has_extension(path, ".stl") || has_extension(path, ".ply")) {
    model = has_extension(path, ".stl") ? import_stl_bundle(bundle, limits, choices)
                                        : import_ply_bundle(bundle, limits, choices);
  } else {
    model = has_extension(path, ".m") ? import_m_bundle(bundle, limits, choices)
                                      : import_obj_bundle(bundle, limits, choices);
  }
  check_import_time(limits, "reading the model");
  LodOptions lod;
  lod.between_levels = [&limits] { check_import_time(limits, "simplifying"); };
  if (model.rig) lod.motion_class = motion_classes(model.mesh, *model.rig);
  // What every step after reading shares: which vertices lie at one point.
  const std::vector<std::uint32_t> position_group = group_by_position(model.mesh.positions);
  prepare_levels_of_detail(model.mesh, position_group, lod);
  check_import_time(limits, "ordering triangles");
  classify_enclosures(model.mesh, position_group);
  find_crease_edges(model.mesh, position_group);
  check_import_time(limits, "finding crease edges");
  IntersectionSearch crossings;
  crossings.deadline = limits.deadline;
  find_intersection_lines(model.mesh, crossings);
  return model;
}

}  // namespace toond::scene
