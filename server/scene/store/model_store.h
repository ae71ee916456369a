#pragma once
// Content-addressed store of uploaded bundles under --data-dir. The id is a
// hash of the bundle's paths and bytes, so the same bundle always gets the
// same id. Every model is written to a temporary folder, fsynced and renamed
// into place, so a crash never leaves a half-written model behind; a model
// leaves by being renamed out of place first, so no reader ever finds half
// of one.
//
// Bounded (StoreOptions::max_bytes), the store lets the least recently used
// models go (last upload or render, scene/store/model_use.h) to make room for a
// new one, but never a model a render holds: this process's own pins (from
// a request's lookup to its answer), and every replica's leases on the
// shared volume (while its render is queued or drawing). Each replica may evict; the
// check and the rename are not one atomic step across replicas, so a render
// that takes a model in the very instant another replica lets it go finds
// it gone (404), as if it had come a moment later; a render that already
// took it draws from memory and is not disturbed.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"
#include "scene/store/store_error.h"
#include "scene/store/store_scan.h"

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
  // What drawing it costs (scene/mesh/render_cost_profile.h): the layers of
  // surface its densest view meets, and the frame-widths of edge it
  // rasterises.
  struct Cost {
    double layers = 0;
    double edge_span = 0;
  } cost;
  // What moves (scene/mesh/rig.h): each clip's name, duration (seconds),
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

struct StoreOptions {
  // Bytes of stored models (their files and info.json) kept at most; 0: no
  // bound, nothing is ever let go.
  std::uint64_t max_bytes = 0;
  // A render's lease older than this is taken for a process that died
  // holding it (scene/store/model_use.h): longer than any request holds a model.
  std::chrono::seconds lease_expiry{600};
};

class ModelStore {
 public:
  // Opens (creating when needed) DIR/models. Leftover temporary folders from
  // an interrupted upload or delete are removed once they are older than
  // kStaleTempAge: replicas share the data directory, so a fresh one may be
  // another process's upload in flight.
  explicit ModelStore(std::filesystem::path data_dir, StoreOptions options = {});
  static constexpr std::chrono::minutes kStaleTempAge{60};

  struct PutResult {
    ModelInfo info;
    bool created = false;  // false: the same bundle was already stored
    // Models let go to keep the store under its bound, least recently
    // used first.
    std::vector<std::string> evicted;
  };
  // Imports the bundle (throws ImportError when it is not a model, and
  // ImportLimitError beyond `limits`), then stores it with `choices`,
  // first letting go what the bound needs. Throws StoreError when it cannot
  // be kept (a full volume, a bound held by renders, a model larger than
  // the bound); nothing of it is left then. Storing it again is a use.
  // Thread-safe.
  PutResult put(const Bundle& bundle, const ImportLimits& limits = {}, const ImportChoices& choices = {});

  std::optional<ModelInfo> info(const std::string& id) const;
  // Whether the model is stored now: one stat, cheap enough for every render
  // (another replica may have removed it).
  bool contains(const std::string& id) const;
  // The bundle; nothing when the model is not stored, or went while it was
  // read (another replica let it go).
  std::optional<Bundle> load(const std::string& id) const;
  std::vector<ModelInfo> list() const;
  bool remove(const std::string& id);

  // A render request holds the model from pin to unpin (scene/store/model_pins.h):
  // this process does not let it go meanwhile. Pinning is a use. Pins nest;
  // ids that are not stored are ignored.
  void pin(const std::string& id);
  void unpin(const std::string& id);
  // While its render is queued or drawing, a lease in the model's folder
  // (scene/store/model_use.h) keeps every replica from letting it go. Leases
  // nest; a request answered from the result cache takes none.
  void lease(const std::string& id);
  void unlease(const std::string& id);

  // Models and bytes in the store (every replica's, on a shared volume).
  StoreUsage usage() const;
  // Models this process let go for the bound since it started.
  std::uint64_t evictions() const { return evictions_; }
  std::uint64_t max_bytes() const { return options_.max_bytes; }
  // The file system the store is on: its size and the bytes still free
  // to this process; nothing when it cannot be asked.
  struct Volume {
    std::uint64_t bytes = 0;
    std::uint64_t free_bytes = 0;
  };
  std::optional<Volume> volume() const;

 private:
  // What make_room() did: the models it let go, or that it let none go
  // because renders hold too much for `incoming` bytes to fit.
  struct Room {
    bool refused = false;
    std::vector<std::string> evicted;
  };
  enum class Letting { Evicted, Gone, Held };

  // Lets the least recently used models go, sparing `spare`, until
  // `incoming` more bytes (and the uploads this process is writing) fit
  // under the bound. `refuse_when_held`: lets none go when the models
  // renders hold leave too little room for `incoming` anyway. Called with
  // evict_mutex_ held.
  Room make_room(std::uint64_t incoming, const std::string& spare, bool refuse_when_held);
  // Whether a render holds the model: a pin here, a lease anywhere. Called
  // with pins_mutex_ held.
  bool held(const std::string& id) const;
  // One model out, unless a render holds it.
  Letting evict(const std::string& id);
  // Renames the model out of place (durably); the folder to delete then,
  // or nothing when the model is not there.
  std::optional<std::filesystem::path> take_out(const std::string& id);
  // Writes the model's folder and renames it into place; false when another
  // upload of the same bundle got there first.
  bool write_model(const std::string& id, const Bundle& bundle, const std::string& info_text);

  std::filesystem::path root_;
  StoreOptions options_;
  std::string holder_;  // this process's name in the lease folders
  mutable std::mutex mutex_;
  // One eviction pass at a time; with it, the uploads this process is
  // writing now (id → how many, and the bytes of one), counted until a
  // scan finds them in place.
  std::mutex evict_mutex_;
  std::unordered_map<std::string, std::pair<int, std::uint64_t>> reserved_;
  std::mutex pins_mutex_;
  std::unordered_map<std::string, int> pins_;
  std::unordered_map<std::string, int> leases_;
  mutable ModelSizes sizes_;
  std::atomic<std::uint64_t> evictions_{0};
};

}  // namespace toond::scene
