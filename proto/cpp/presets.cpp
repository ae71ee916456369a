#include "presets.h"

#include "toond_proto_files.h"

namespace toond::proto {

const Presets& Presets::builtin() {
  static const Presets presets(nlohmann::json::parse(toond::proto_files::find("presets.json")),
                               nlohmann::json::parse(toond::proto_files::find("camera-presets.json")));
  return presets;
}

nlohmann::json merge_over(const nlohmann::json& base, const nlohmann::json& over) {
  if (!base.is_object() || !over.is_object()) return over;
  nlohmann::json out = base;
  for (const auto& [key, value] : over.items()) {
    out[key] = out.contains(key) ? merge_over(out[key], value) : value;
  }
  return out;
}

nlohmann::json Presets::expand(const nlohmann::json& request) const {
  if (!request.is_object() || !request.contains("preset")) return expand_camera(request);
  const auto preset = document_.find(request["preset"].get<std::string>());
  if (preset == document_.end()) return expand_camera(request);
  return expand_camera(merge_over(preset->at("params"), request));
}

nlohmann::json Presets::expand_camera(nlohmann::json request) const {
  if (!request.is_object() || !request.contains("camera")) return request;
  nlohmann::json& camera = request["camera"];
  if (!camera.is_object() || !camera.contains("preset") || !camera["preset"].is_string()) return request;
  const auto preset = camera_document_.find(camera["preset"].get<std::string>());
  if (preset == camera_document_.end()) return request;
  camera = merge_over(preset->at("camera"), camera);
  return request;
}

}  // namespace toond::proto
