#pragma once
// Named looks (proto/presets.json): each is a partial set of render
// parameters. A request naming a preset gets the preset's fields first and
// its own fields on top, object by object, so `{"preset":"bw_comic",
// "outline":{"width":4}}` keeps the rest of the preset's outline.
#include <nlohmann/json.hpp>

namespace toond::proto {

class Presets {
 public:
  // The presets embedded at build time.
  static const Presets& builtin();
  explicit Presets(nlohmann::json document) : document_(std::move(document)) {}

  // {"name": {"description": …, "params": {…}}, …}
  const nlohmann::json& document() const { return document_; }

  // The request with its preset's parameters filled in underneath; a request
  // without "preset" comes back unchanged. The name must already have been
  // validated against the schema's enum (ParamSchema::validate).
  nlohmann::json expand(const nlohmann::json& request) const;

 private:
  nlohmann::json document_;
};

// `over` merged onto `base`: objects merge key by key, anything else
// (numbers, strings, arrays) in `over` replaces what `base` had.
nlohmann::json merge_over(const nlohmann::json& base, const nlohmann::json& over);

}  // namespace toond::proto
