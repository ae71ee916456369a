#pragma once
// A clip range given in frames on toon's command line
// (`--set sheet.animation.range=168f,187f`): recognised in the text, and
// turned into the seconds the wire takes by the clip's frame rate, which
// the daemon's description of the model lists (GET /models/ID). A range in
// seconds ("2.8,3.1167") is the schema's to read, as any --set is.
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace toond::cli {

struct FrameRange {
  double first = 0;
  double last = 0;
};

// The frames of `text` when `key` names a clip range (`animation.range`,
// `sheet.animation.range`, `sheet.animation.N.range`) and every number of
// `text` says `f`: "168f,187f", "168f, 187f" or "[168f,187f]". nullopt
// when no number says `f` (seconds). UsageError when some do and some do
// not, or the text is not two such numbers.
std::optional<FrameRange> frame_range_of(std::string_view key, std::string_view text);

// The model's clips as GET /models/ID lists them (`animation.clips`: name,
// duration, frame_rate where the format has one).
using ClipsOfModel = std::function<nlohmann::json(const std::string& model_id)>;

// `frames` as the range in seconds a --set of `key` gives ("2.8,3.1166…"):
// frame f at f / frame_rate of the clip that the key's entry in `params`
// names (its `clip`, by name, by the part after '|', or by index).
// UsageError when `params` name no stored model, the entry no clip, the
// model has no such clip, or the clip no frame rate. `text` is the --set's
// own, for the messages.
std::string range_in_seconds(const nlohmann::json& params, const std::string& key, const std::string& text,
                             FrameRange frames, const ClipsOfModel& clips_of);

}  // namespace toond::cli
