#include "frame_ranges.h"

#include <charconv>
#include <cstdio>
#include <vector>

#include "cli_args.h"

namespace toond::cli {
namespace {

using nlohmann::json;

std::vector<std::string> dotted_segments(std::string_view key) {
  std::vector<std::string> segments;
  for (std::size_t start = 0; start <= key.size();) {
    std::size_t dot = key.find('.', start);
    if (dot == std::string_view::npos) dot = key.size();
    segments.emplace_back(key.substr(start, dot - start));
    start = dot + 1;
  }
  return segments;
}

bool names_clip_range(std::string_view key) {
  return key == "animation.range" || (key.starts_with("sheet.animation.") && key.ends_with(".range"));
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// One number of the list and whether it says `f`; nullopt when it is not
// a number.
struct Number {
  double value = 0;
  bool frames = false;
};
std::optional<Number> number_of(std::string_view text) {
  text = trimmed(text);
  Number number;
  if (!text.empty() && text.back() == 'f') {
    number.frames = true;
    text.remove_suffix(1);
  }
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number.value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return number;
}

// The entry a range's key sits in (`sheet.animation.1` of
// `sheet.animation.1.range`), or null when params do not hold it.
const json* entry_of(const json& params, const std::string& key) {
  const std::vector<std::string> segments = dotted_segments(key);
  const json* node = &params;
  for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
    const std::string& segment = segments[i];
    if (node->is_object() && node->contains(segment)) {
      node = &(*node)[segment];
    } else if (node->is_array() && !segment.empty() && segment.find_first_not_of("0123456789") == std::string::npos &&
               std::stoul(segment) < node->size()) {
      node = &(*node)[std::stoul(segment)];
    } else {
      return nullptr;
    }
  }
  return node->is_object() ? node : nullptr;
}

// The clip `clip` names among `clips`, as the daemon finds it.
const json* find_clip(const json& clips, const json& clip) {
  if (!clips.is_array()) return nullptr;
  if (clip.is_number_integer()) {
    const auto index = clip.get<long long>();
    return index >= 0 && static_cast<std::size_t>(index) < clips.size() ? &clips[static_cast<std::size_t>(index)]
                                                                        : nullptr;
  }
  if (!clip.is_string()) return nullptr;
  const std::string name = clip;
  const json* by_tail = nullptr;
  int tails = 0;
  for (const json& c : clips) {
    const std::string have = c.value("name", "");
    if (have == name) return &c;
    if (have.ends_with("|" + name)) by_tail = &c, ++tails;
  }
  return tails == 1 ? by_tail : nullptr;
}

std::string seconds_text(FrameRange frames, double frame_rate) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g,%.17g", frames.first / frame_rate, frames.last / frame_rate);
  return text;
}

}  // namespace

std::optional<FrameRange> frame_range_of(std::string_view key, std::string_view text) {
  if (!names_clip_range(key)) return std::nullopt;
  std::string_view list = trimmed(text);
  if (list.size() >= 2 && list.front() == '[' && list.back() == ']') list = list.substr(1, list.size() - 2);
  const std::size_t comma = list.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  const std::optional<Number> first = number_of(list.substr(0, comma));
  const std::optional<Number> last = number_of(list.substr(comma + 1));
  if (!first || !last || (!first->frames && !last->frames)) return std::nullopt;
  if (!first->frames || !last->frames) {
    throw UsageError("--set " + std::string(key) + "=" + std::string(text) +
                     ": give both ends in frames (168f,187f) or both in seconds (2.8,3.1167)");
  }
  return FrameRange{first->value, last->value};
}

std::string range_in_seconds(const json& params, const std::string& key, const std::string& text, FrameRange frames,
                             const ClipsOfModel& clips_of) {
  const std::string assignment = "--set " + key + "=" + text;
  const auto model = params.find("model");
  if (model == params.end() || !model->is_string() || !clips_of) {
    throw UsageError(assignment +
                     ": a range in frames needs a stored model (--model ID), whose clip's frame rate "
                     "turns frames into seconds; upload it first (toon upload), or give the range in seconds");
  }
  const json* entry = entry_of(params, key);
  if (!entry || !entry->contains("clip")) {
    const std::string entry_key = key.substr(0, key.size() - std::string(".range").size());
    throw UsageError(assignment + ": a range in frames needs its clip first (--set " + entry_key + ".clip=NAME)");
  }
  const json& clip = (*entry)["clip"];
  const json clips = clips_of(model->get<std::string>());
  const json* found = find_clip(clips, clip);
  if (!found) throw UsageError(assignment + ": the model has no clip " + clip.dump());
  if (!found->contains("frame_rate") || !(*found)["frame_rate"].is_number() ||
      !((*found)["frame_rate"].get<double>() > 0.0)) {
    throw UsageError(assignment + ": clip " + clip.dump() +
                     " has no frame rate (its file keys by seconds, as glTF does); give the range in seconds");
  }
  return seconds_text(frames, (*found)["frame_rate"].get<double>());
}

}  // namespace toond::cli
