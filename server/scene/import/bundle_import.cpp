#include "scene/import/bundle_import.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <vector>

#include "bundle_paths/bundle_path.h"
#include "bundle_paths/model_formats.h"
#include "scene/animation/motion_classes.h"
#include "scene/gltf/gltf_container.h"
#include "scene/gltf/gltf_import.h"
#include "scene/import/assimp_import.h"
#include "scene/import/clip_merge.h"
#include "scene/import/iqm_import.h"
#include "scene/import/m_import.h"
#include "scene/import/obj_import.h"
#include "scene/import/ply_import.h"
#include "scene/import/skins.h"
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
  std::vector<std::string> paths;
  for (const auto& [path, content] : bundle.files()) paths.push_back(path);
  return find_model_file_among(bundle, paths, extensions, noun);
}

std::string find_model_file_among(const Bundle& bundle, const std::vector<std::string>& paths,
                                  std::span<const std::string_view> extensions, std::string_view noun) {
  std::vector<std::string> found;
  for (const std::string& path : paths) {
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

// The file the bundle's model is read from, and whether it is glTF; the
// files beside it holding a skeleton's animation alone, whose clips it
// takes (clip_merge.h, iqm_import.h).
struct ModelFile {
  std::string path;
  bool gltf = false;
  std::vector<std::string> clip_files;
};

bool is_gltf_path(std::string_view path) { return has_extension(path, ".gltf") || has_extension(path, ".glb"); }

// Whether a file holds a skeleton's animation and no mesh, told from its
// bytes without converting it: MD5's and BVH's animation files always; IQM
// and glTF files by what they hold.
bool holds_clips_alone(std::string_view path, std::string_view content) {
  if (has_extension(path, ".md5anim") || has_extension(path, ".bvh")) return true;
  if (has_extension(path, ".iqm")) {
    const auto contents = iqm_contents(content);
    return contents && contents->meshes == 0 && contents->clips > 0;
  }
  if (is_gltf_path(path) || looks_like_gltf(content)) {
    const auto contents = gltf_contents(content);
    return contents && !contents->meshes && !contents->clips.empty();
  }
  return false;
}

// What a file holding clips alone holds, in words for the answer to an
// upload of it alone.
std::string clips_alone_refusal(const std::string& path, std::string_view content) {
  std::string what = "an animation";
  if (const auto iqm = iqm_contents(content)) {
    what = std::to_string(iqm->clips) + (iqm->clips == 1 ? " clip" : " clips") +
           (iqm->clip_names.empty() ? "" : " ('" + iqm->clip_names.front() + "'") +
           (iqm->clip_names.empty()      ? ""
            : iqm->clip_names.size() > 1 ? ", ...)"
                                         : ")") +
           " for a skeleton of " + std::to_string(iqm->poses) + " joints";
  } else if (const auto gltf = gltf_contents(content)) {
    what = std::to_string(gltf->clips.size()) + (gltf->clips.size() == 1 ? " clip" : " clips") + " moving " +
           std::to_string(gltf->nodes) + " joints";
  }
  return path + " holds only " + what +
         " and no mesh to draw: upload it together with the model it animates (the file with the mesh and its "
         "skeleton, e.g. a character's .iqm, .md5mesh, .fbx or .glb) in one upload, and its clips are added to "
         "that model by joint name";
}

// The assimp helper's answers for files of the bundle, kept so that a file
// converted to tell what it holds is not converted again to read it.
using Conversions = std::map<std::string, ConvertedFile>;

const ConvertedFile& converted(const Bundle& bundle, const std::string& path, const ImportLimits& limits,
                               Conversions& conversions) {
  const auto it = conversions.find(path);
  if (it != conversions.end()) return it->second;
  return conversions.emplace(path, convert_with_assimp(bundle, path, limits)).first->second;
}

// Several model files none of whose bytes say which holds clips alone (an
// FBX character and its animation-only FBX files): those of the assimp
// helper's formats are converted, and their glTF says.
void sort_by_conversion(const Bundle& bundle, std::vector<std::string>& candidates,
                        std::vector<std::string>& clip_files, const ImportLimits& limits, Conversions& conversions) {
  std::vector<std::string> models;
  for (const std::string& path : candidates) {
    bool clips_alone = false;
    if (read_through_assimp(path) && !has_extension(path, ".gltf") && !has_extension(path, ".glb")) {
      const auto contents = gltf_contents(converted(bundle, path, limits, conversions).glb);
      clips_alone = contents && !contents->meshes && !contents->clips.empty();
    }
    (clips_alone ? clip_files : models).push_back(path);
  }
  candidates = std::move(models);
}

// `conversions` given, several candidates are told apart by converting
// them (sort_by_conversion); without, only by their bytes.
ModelFile model_file(const Bundle& bundle, const ImportLimits& limits = {}, Conversions* conversions = nullptr) {
  ModelFile file;
  std::vector<std::string> candidates;
  for (const auto& [path, content] : bundle.files()) {
    const bool model_like = bundle_paths::is_model_file(path) || has_extension(path, ".md5anim") ||
                            has_extension(path, ".bvh") ||
                            (!has_extension(path, ".obj") && !has_extension(path, ".mtl") &&
                             !has_extension(path, ".m") && looks_like_gltf(content));
    if (!model_like) continue;
    if (holds_clips_alone(path, content)) {
      file.clip_files.push_back(path);
    } else {
      candidates.push_back(path);
    }
  }
  if (candidates.size() > 1 && conversions)
    sort_by_conversion(bundle, candidates, file.clip_files, limits, *conversions);
  if (candidates.empty() && !file.clip_files.empty()) {
    const std::string& first = file.clip_files.front();
    throw ImportError(first, clips_alone_refusal(first, *bundle.find(first)));
  }
  const std::vector<std::string> gltf = gltf_files(bundle);
  std::vector<std::string> gltf_models;
  for (const std::string& path : gltf) {
    if (std::find(candidates.begin(), candidates.end(), path) != candidates.end()) gltf_models.push_back(path);
  }
  const bool obj_or_m = std::any_of(candidates.begin(), candidates.end(), [](const std::string& path) {
    return has_extension(path, ".obj") || has_extension(path, ".m");
  });
  if (gltf_models.size() == 1 && !obj_or_m) {
    file.path = gltf_models.front();
    file.gltf = true;
    return file;
  }
  std::vector<std::string_view> extensions = model_extensions();
  file.path = find_model_file_among(bundle, candidates, extensions, kModelFileNoun);
  file.gltf = is_gltf_path(file.path);
  return file;
}

// The bytes a glTF file of the bundle names by URI, relative to it.
BufferFiles buffers_beside(const Bundle& bundle, const std::string& path) {
  return [&bundle, path](const std::string& uri) -> std::optional<std::string> {
    const auto found = bundle.resolve(path, bundle_paths::uri_reference(uri));
    if (!found) return std::nullopt;
    return *bundle.find(*found);
  };
}

// The model read as glTF (as uploaded, or converted: by the assimp helper,
// or from IQM), with the clips of the files beside it holding clips alone
// added by joint name.
Model import_with_clips(const Bundle& bundle, const ModelFile& file, const ImportLimits& limits,
                        const ImportChoices& choices, Conversions& conversions) {
  const std::string& path = file.path;
  const bool iqm = has_extension(path, ".iqm");
  std::vector<std::string> iqm_clips;
  std::vector<std::string> other_clips;
  for (const std::string& clips : file.clip_files)
    (has_extension(clips, ".iqm") ? iqm_clips : other_clips).push_back(clips);
  if (file.gltf && other_clips.empty()) return import_gltf_bundle(bundle, path, limits, choices);
  if (iqm && other_clips.empty()) return import_iqm_bundle(bundle, path, iqm_clips, limits, choices);
  std::vector<std::string> warnings;
  for (const std::string& clips : iqm_clips) {
    if (!iqm) warnings.push_back(clips + ": IQM clips go onto an IQM model only; not read");
  }
  std::optional<ConvertedFile> converted;
  std::vector<double> iqm_rates;
  std::string gltf;
  if (file.gltf) {
    gltf = *bundle.find(path);
  } else if (iqm) {
    gltf = iqm_glb(bundle, path, iqm_clips, warnings, iqm_rates, limits);
  } else {
    converted = scene::converted(bundle, path, limits, conversions);
    gltf = converted->glb;
    // A file of clips alone, uploaded alone: what the helper made of it says so.
    if (const auto contents = gltf_contents(gltf); contents && !contents->meshes && !contents->clips.empty()) {
      throw ImportError(path, clips_alone_refusal(path, gltf));
    }
  }
  std::vector<std::pair<ConvertedFile, std::vector<std::size_t>>> sources;
  for (const std::string& clips : other_clips) {
    ConvertedFile source = looks_like_gltf(*bundle.find(clips)) ? ConvertedFile{*bundle.find(clips), {}}
                                                                : scene::converted(bundle, clips, limits, conversions);
    MergedClips merged = merge_clips(gltf, path, source.glb, clips, buffers_beside(bundle, clips), warnings);
    gltf = std::move(merged.gltf);
    sources.emplace_back(std::move(source), std::move(merged.added));
  }
  const GltfOrigin origin = file.gltf ? GltfOrigin::File : GltfOrigin::Converted;
  Model model = import_gltf_bundle(with_file(bundle, path, std::move(gltf)), path, limits, choices, origin);
  std::size_t own_clips = model.rig ? model.rig->clips.size() : 0;
  for (const auto& [source, added] : sources) own_clips -= std::min(own_clips, added.size());
  if (converted) {
    std::vector<std::size_t> own(own_clips);
    for (std::size_t c = 0; c < own.size(); ++c) own[c] = c;
    add_converter_notes(*converted, path, model, 0, own);
  }
  std::size_t first = own_clips;
  for (std::size_t k = 0; k < sources.size(); ++k) {
    add_converter_notes(sources[k].first, other_clips[k], model, first, sources[k].second);
    first += sources[k].second.size();
  }
  if (model.rig && !iqm_rates.empty()) {
    auto rig = std::make_shared<Rig>(*model.rig);
    for (std::size_t c = 0; c < iqm_rates.size() && c < rig->clips.size(); ++c) rig->clips[c].frame_rate = iqm_rates[c];
    model.rig = std::move(rig);
  }
  model.warnings.insert(model.warnings.end(), warnings.begin(), warnings.end());
  return model;
}

// The model file whose format's convention settles `up`: told from the
// bytes, or, where only converting would tell (several FBX files), the
// first model file (such files say their axes themselves).
std::string model_path_for_up(const Bundle& bundle) {
  try {
    return model_file(bundle).path;
  } catch (const ImportError&) {
    for (const auto& [path, content] : bundle.files()) {
      if (bundle_paths::is_model_file(path)) return path;
    }
    throw;
  }
}

}  // namespace

bool z_up_by_convention(std::string_view path) {
  for (const std::string_view extension : {".stl", ".ply", ".3mf", ".amf", ".iqm"}) {
    if (has_extension(path, extension)) return true;
  }
  return false;
}

ImportChoices with_format_up(const Bundle& bundle, ImportChoices choices) {
  if (choices.up == ImportChoices::Up::FormatDefault) {
    choices.up = z_up_by_convention(model_path_for_up(bundle)) ? ImportChoices::Up::Z : ImportChoices::Up::Y;
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
  Conversions conversions;
  const ModelFile file = model_file(bundle, limits, &conversions);
  const std::string& path = file.path;
  if (choices.gltf_scene && !file.gltf) {
    throw ImportError(path, path + ": a scene was asked for, but only glTF files have scenes");
  }
  Model model;
  if (file.gltf || read_through_assimp(path) || has_extension(path, ".iqm")) {
    model = import_with_clips(bundle, file, limits, choices, conversions);
  } else if (has_extension(path, ".stl") || has_extension(path, ".ply")) {
    model = has_extension(path, ".stl") ? import_stl_bundle(bundle, limits, choices)
                                        : import_ply_bundle(bundle, limits, choices);
  } else {
    model = has_extension(path, ".m") ? import_m_bundle(bundle, limits, choices)
                                      : import_obj_bundle(bundle, limits, choices);
  }
  put_skins(model, bundle, path, choices, limits);
  apply_format_conventions(model, path);
  warn_unused_images(model, bundle);
  if (!file.clip_files.empty() && !model.rig && !file.gltf && !read_through_assimp(path) &&
      !has_extension(path, ".iqm")) {
    model.warnings.push_back(path + " has no skeleton: the clips of " + file.clip_files.front() +
                             (file.clip_files.size() > 1 ? " and the others" : "") + " are not read");
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
