#pragma once
// Content-addressed store of uploaded bundles under --data-dir. The id is a
// hash of the bundle's paths and bytes, so the same bundle always gets the
// same id. Every model is written to a temporary folder, fsynced and renamed
// into place, so a crash never leaves a half-written model behind.
#include <chrono>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/bundle.h"
#include "scene/import_choices.h"
#include "scene/import_limits.h"

namespace toond::scene {

// What an upload answer and GET /models report about a model.
struct ModelInfo {
  std::string id;
  std::size_t triangles = 0;
  std::size_t materials = 0;
  std::size_t textures = 0;
  std::size_t bytes = 0;
  std::vector<std::string> files;
  std::vector<std::string> warnings;
  // Positions closer than `tolerance` (model units) were welded into one
  // for everything derived from topology; `positions` were moved.
  struct Weld {
    double tolerance = 0;
    std::size_t positions = 0;
  } weld;
  // What drawing it costs (scene/render_cost_profile.h): the layers of
  // surface its densest view meets, and the frame-widths of edge it
  // rasterises.
  struct Cost {
    double layers = 0;
    double edge_span = 0;
  } cost;
  // What moves (scene/rig.h): each clip's name, duration (seconds),
  // channel count and frame rate (where the format has one), the skins'
  // joints and the morph targets. Empty clips and zero counts: nothing
  // moves.
  struct ClipInfo {
    std::string name;
    double duration = 0;
    std::size_t channels = 0;
    std::optional<double> frame_rate;
  };
  struct Animation {
    std::vector<ClipInfo> clips;
    std::size_t joints = 0;
    std::size_t morph_targets = 0;
    bool any() const { return !clips.empty() || joints > 0 || morph_targets > 0; }
  } animation;
  // What the upload asked of the import (a glTF scene), kept so that a
  // re-import makes the same model.
  ImportChoices choices;

  nlohmann::json to_json() const;
  static ModelInfo from_json(const nlohmann::json& j);
};

// The content-addressed id of a bundle: 32 hex digits of SHA-256 over the
// sorted (path, size, bytes) records, and the import choices where any is
// made (the same files with another glTF scene are another model).
std::string bundle_id(const Bundle& bundle, const ImportChoices& choices = {});

class ModelStore {
 public:
  // Opens (creating when needed) DIR/models. Leftover temporary folders from
  // an interrupted upload or delete are removed once they are older than
  // kStaleTempAge: replicas share the data directory, so a fresh one may be
  // another process's upload in flight.
  explicit ModelStore(std::filesystem::path data_dir);
  static constexpr std::chrono::minutes kStaleTempAge{60};

  struct PutResult {
    ModelInfo info;
    bool created = false;  // false: the same bundle was already stored
  };
  // Imports the bundle (throws ImportError when it is not a model, and
  // ImportLimitError beyond `limits`), then stores it with `choices`.
  // Thread-safe.
  PutResult put(const Bundle& bundle, const ImportLimits& limits = {}, const ImportChoices& choices = {});

  std::optional<ModelInfo> info(const std::string& id) const;
  // Whether the model is stored now: one stat, cheap enough for every render
  // (another replica may have removed it).
  bool contains(const std::string& id) const;
  std::optional<Bundle> load(const std::string& id) const;
  std::vector<ModelInfo> list() const;
  bool remove(const std::string& id);

 private:
  std::filesystem::path root_;
  mutable std::mutex mutex_;
};

}  // namespace toond::scene
