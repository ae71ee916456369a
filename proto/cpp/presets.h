#pragma once
// Named looks (proto/presets.json): each is a partial set of render
// parameters. A request naming a preset gets the preset's fields first and
// its own fields on top, object by object, so `{"preset":"bw_comic",
// "outline":{"width":4}}` keeps the rest of the preset's outline. A camera
// preset (`camera.preset`, proto/camera-presets.json) fills the camera the
// same way, so it combines with any look.
#include <nlohmann/json.hpp>

namespace toond::proto {

class Presets {
 public:
  // The presets embedded at build time.
  static const Presets& builtin();
  explicit Presets(nlohmann::json document, nlohmann::json camera_document = nlohmann::json::object())
      : document_(std::move(document)), camera_document_(std::move(camera_document)) {}

  // {"name": {"description": …, "params": {…}}, …}
  const nlohmann::json& document() const { return document_; }

  // {"isometric": {"description": …, "camera": {…}}, …}
  const nlohmann::json& camera_document() const { return camera_document_; }

  // The request with its preset's parameters filled in underneath, then its
  // camera preset's under its camera; a request naming neither comes back
  // unchanged. The names must already have been validated against the
  // schema's enums (ParamSchema::validate).
  nlohmann::json expand(const nlohmann::json& request) const;

 private:
  nlohmann::json expand_camera(nlohmann::json request) const;

  nlohmann::json document_;
  nlohmann::json camera_document_;
};

// `over` merged onto `base`: objects merge key by key, anything else
// (numbers, strings, arrays) in `over` replaces what `base` had.
nlohmann::json merge_over(const nlohmann::json& base, const nlohmann::json& over);

}  // namespace toond::proto
