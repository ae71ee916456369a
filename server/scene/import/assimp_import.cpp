#include "scene/import/assimp_import.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "bundle_paths/model_formats.h"
#include "helpers/launch/helper_program.h"
#include "scene/gltf/gltf_container.h"
#include "scene/gltf/gltf_import.h"
#include "scene/import/bundle_import.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

std::string lower_extension(std::string_view path) {
  for (const std::string_view extension : bundle_paths::assimp_model_extensions()) {
    if (has_extension(path, extension)) return std::string(extension.substr(1));
  }
  return {};
}

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](char c) { return c >= 'a' && c <= 'z' ? c - 32 : c; });
  return text;
}

// More frames a second than any format's clips are keyed at.
constexpr double kMaxFrameRate = 10000.0;

std::uint64_t capped_sum(std::uint64_t base, std::uint64_t factor, std::uint64_t bytes) {
  const std::uint64_t cap = std::uint64_t{1} << 40;
  return bytes > cap / factor ? cap : std::min(cap, base + factor * bytes);
}

// assimp holds the file, its own scene of it and the glTF it writes, with
// the tables a format's reader builds on the way: sixteen times the file
// and a base for the program and its libraries. A compressed FBX expands
// several times; what it expands to is bounded by the answer's cap.
std::uint64_t memory_mb_for(std::size_t file_bytes) { return capped_sum(512ull << 20, 16, file_bytes) >> 20; }

// The glTF answer holds floats where most of these formats hold floats or
// doubles, and embedded images as they were: 32 times the file covers
// FBX's zlib-compressed arrays.
std::size_t answer_cap(std::size_t file_bytes) {
  return static_cast<std::size_t>(
      std::min<std::uint64_t>(capped_sum(64ull << 20, 32, file_bytes), std::numeric_limits<std::size_t>::max() / 2));
}

std::chrono::milliseconds time_left(const ImportLimits& limits) {
  if (limits.deadline == std::chrono::steady_clock::time_point::max()) return kAssimpTimeLimit;
  const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(limits.deadline - std::chrono::steady_clock::now());
  return std::clamp(left, std::chrono::milliseconds(1), kAssimpTimeLimit);
}

// The helper's notes ("note: 2 cameras not read"), each a warning naming
// the file; anything else it wrote is not trusted to be a sentence.
void add_notes(const std::string& errors, const std::string& path, std::vector<std::string>& warnings) {
  std::size_t at = 0;
  while (at < errors.size()) {
    const std::size_t end = std::min(errors.find('\n', at), errors.size());
    const std::string line = errors.substr(at, end - at);
    if (line.starts_with("note: ")) warnings.insert(warnings.begin(), path + ": " + helper_reason(line.substr(6)));
    at = end + 1;
  }
}

// The helper's "frame_rate: CLIP FPS" lines, each clip's frames a second,
// onto the clips read from its answer; a line that does not name one of
// them with a rate a clip could have is not trusted.
void add_frame_rates(const std::string& errors, Model& model) {
  if (!model.rig) return;
  std::vector<std::pair<std::size_t, double>> rates;
  std::size_t at = 0;
  while (at < errors.size()) {
    const std::size_t end = std::min(errors.find('\n', at), errors.size());
    const std::string line = errors.substr(at, end - at);
    at = end + 1;
    constexpr std::string_view kPrefix = "frame_rate: ";
    if (!line.starts_with(kPrefix)) continue;
    const char* const last = line.data() + line.size();
    std::size_t clip = 0;
    double rate = 0;
    const auto [space, clip_error] = std::from_chars(line.data() + kPrefix.size(), last, clip);
    if (clip_error != std::errc() || space == last || *space != ' ') continue;
    const auto [end_of_rate, rate_error] = std::from_chars(space + 1, last, rate);
    if (rate_error != std::errc() || end_of_rate != last) continue;
    if (clip < model.rig->clips.size() && std::isfinite(rate) && rate > 0.0 && rate <= kMaxFrameRate) {
      rates.emplace_back(clip, rate);
    }
  }
  if (rates.empty()) return;
  auto rig = std::make_shared<Rig>(*model.rig);
  for (const auto& [clip, rate] : rates) rig->clips[clip].frame_rate = rate;
  model.rig = std::move(rig);
}

// The bundle with the model file's bytes replaced by the helper's glTF, so
// the glTF importer names the original file in everything it says and finds
// textures beside it.
Bundle with_converted_file(const Bundle& bundle, const std::string& path, std::string glb) {
  Bundle converted;
  for (const auto& [name, content] : bundle.files()) {
    if (name != path) converted.add(name, content);
  }
  converted.add(path, std::move(glb));
  return converted;
}

}  // namespace

bool read_through_assimp(std::string_view path) { return !lower_extension(path).empty(); }

std::filesystem::path assimp_converter_program() {
  return helper_program("TOOND_ASSIMP_CONVERTER", "toond-assimp-convert");
}

Model import_assimp_bundle(const Bundle& bundle, const std::string& path, const ImportLimits& limits,
                           const ImportChoices& choices) {
  const std::string* content = bundle.find(path);
  const std::string format = lower_extension(path);
  if (!content || format.empty()) throw ImportError(path, path + ": not a file read through assimp");
  check_import_time(limits, "starting to read " + path);

  ChildRun run;
  run.program = assimp_converter_program().string();
  run.time_limit = time_left(limits);
  run.arguments = {"--format",      format,
                   "--memory-mb",   std::to_string(memory_mb_for(content->size())),
                   "--cpu-seconds", std::to_string(helper_cpu_seconds(run.time_limit))};
  run.input = *content;
  run.max_output = answer_cap(content->size());
  ChildResult result;
  try {
    result = run_helper(run, "the " + upper(format) + " reader", "answered more than such a file can hold");
  } catch (const HelperError& e) {
    throw ImportError(path, path + ": " + e.what());
  }
  if (!looks_like_gltf(result.output)) {
    throw ImportError(path, path + ": the " + upper(format) + " reader answered something other than glTF");
  }
  Model model = import_gltf_bundle(with_converted_file(bundle, path, std::move(result.output)), path, limits, choices,
                                   GltfOrigin::Converted);
  add_notes(result.errors, path, model.warnings);
  add_frame_rates(result.errors, model);
  return model;
}

}  // namespace toond::scene
