#include "scene/import/assimp_import.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

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

// The helper's "frame_rate: CLIP FPS" lines, each clip's frames a second
// by its index in the converted file; a line that does not name a clip with
// a rate a clip could have is not trusted.
std::map<std::size_t, double> frame_rates(const std::string& errors) {
  std::map<std::size_t, double> rates;
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
    if (std::isfinite(rate) && rate > 0.0 && rate <= kMaxFrameRate) rates[clip] = rate;
  }
  return rates;
}

}  // namespace

bool read_through_assimp(std::string_view path) { return !lower_extension(path).empty(); }

std::filesystem::path assimp_converter_program() {
  return helper_program("TOOND_ASSIMP_CONVERTER", "toond-assimp-convert");
}

ConvertedFile convert_with_assimp(const Bundle& bundle, const std::string& path, const ImportLimits& limits) {
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
  return {std::move(result.output), std::move(result.errors)};
}

void add_converter_notes(const ConvertedFile& converted, const std::string& path, Model& model, std::size_t first_clip,
                         const std::vector<std::size_t>& clips) {
  add_notes(converted.notes, path, model.warnings);
  if (!model.rig) return;
  const std::map<std::size_t, double> rates = frame_rates(converted.notes);
  if (rates.empty()) return;
  auto rig = std::make_shared<Rig>(*model.rig);
  for (std::size_t k = 0; k < clips.size() && first_clip + k < rig->clips.size(); ++k) {
    if (const auto it = rates.find(clips[k]); it != rates.end()) rig->clips[first_clip + k].frame_rate = it->second;
  }
  model.rig = std::move(rig);
}

Model import_assimp_bundle(const Bundle& bundle, const std::string& path, const ImportLimits& limits,
                           const ImportChoices& choices) {
  ConvertedFile converted = convert_with_assimp(bundle, path, limits);
  Model model =
      import_gltf_bundle(with_file(bundle, path, converted.glb), path, limits, choices, GltfOrigin::Converted);
  std::vector<std::size_t> own(model.rig ? model.rig->clips.size() : 0);
  for (std::size_t c = 0; c < own.size(); ++c) own[c] = c;
  add_converter_notes(converted, path, model, 0, own);
  return model;
}

}  // namespace toond::scene
