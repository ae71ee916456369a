#pragma once
// Content-addressed store of uploaded bundles under --data-dir. The id is a
// hash of the bundle's paths and bytes, so the same bundle always gets the
// same id. Every model is written to a temporary folder, fsynced and renamed
// into place, so a crash never leaves a half-written model behind; a model
// leaves by being renamed out of place first, so no reader ever finds half
// of one.
//
// The store's index (scene/store/store_catalog.h) knows every model's size
// and last use, so that landing an upload, letting models go and counting
// the store cost O(log n) in the number of models, never a walk of the
// store. It is shared by every replica on the volume, and changed in one
// pass at a time across them.
//
// Bounded (StoreOptions::max_bytes), the store lets the least recently used
// models go (last upload or render, scene/store/model_use.h) to make room for
// a new one, in the pass that renames the new one in: the store never holds
// more than its bound, and lets go no more than it needs. It never lets go
// a model a render holds: this process's own pins (from a request's lookup
// to its answer), and every replica's leases on the shared volume (while
// its render is queued or drawing). A render that takes a model in the
// very instant another replica lets it go finds it gone (404), as if it had
// come a moment later; a render that already took it draws from memory and
// is not disturbed.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"
#include "scene/store/folder_sweeper.h"
#include "scene/store/store_catalog.h"
#include "scene/store/store_error.h"
#include "scene/store/store_journal.h"
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
  // Each material as it is drawn: its colour texture's bundle path ("" for
  // none; an embedded image is named by its file and index), its alpha mode
  // ("opaque", "mask", "blend") and cutoff, and whether the file says it is
  // matte. Models stored before this was kept have none listed.
  struct MaterialEntry {
    std::string name;
    std::string texture;
    std::string alpha;
    double alpha_cutoff = 0.5;
    bool matte = false;
  };
  std::vector<MaterialEntry> material_list;

  nlohmann::json to_json() const;
  static ModelInfo from_json(const nlohmann::json& j);
};

// The content-addressed id of a bundle: 32 hex digits of SHA-256 over the
// sorted (path, size, bytes) records, and the import choices where any is
// made (the same files with another glTF scene are another model).
std::string bundle_id(const Bundle& bundle, const ImportChoices& choices = {});

struct Model;

// `model`'s materials as ModelInfo lists them.
std::vector<ModelInfo::MaterialEntry> material_entries(const Model& model);

struct StoreOptions {
  // Bytes of stored models (their files and info.json) kept at most; 0: no
  // bound, nothing is ever let go.
  std::uint64_t max_bytes = 0;
  // A render's lease older than this is taken for a process that died
  // holding it (scene/store/model_use.h): longer than any request holds a model.
  std::chrono::seconds lease_expiry{600};
  // How long a change waits for the store's lock, which another replica
  // holds for a pass of a few file operations, before it gives up
  // (StoreError::Kind::Busy): a replica hung while it holds the lock stops
  // others' uploads for this long each, not for ever.
  std::chrono::milliseconds lock_wait{30000};
  // Where the store tells the operator what it did on its own (an index
  // rebuilt); standard error, as "toond: …", when empty.
  std::function<void(const std::string&)> log;
  // Called at named moments of a pass, for tests that stop a replica there:
  // "intended" (the index knows what is about to come and go), "evicting"
  // (after each model renamed out), "renamed" (the new model in place, the
  // index not yet told).
  std::function<void(std::string_view moment)> checkpoint;
};

class ModelStore {
 public:
  // Opens (creating when needed) DIR/models and its index (DIR/models.index,
  // read when intact, rebuilt with a log line when missing or damaged).
  // Leftover temporary folders from an interrupted upload or delete are
  // removed once they are older than kStaleTempAge: replicas share the data
  // directory, so a fresh one may be another process's upload in flight.
  // Throws StoreError when the index cannot be read or made.
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
  // the bound, the store locked by a hung replica); nothing of it is left
  // then. Storing it again is a use.
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

  // Models and bytes in the store (every replica's, on a shared volume), as
  // its index has them.
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
  // The models a pass lets go to make room: intents for the index, least
  // recently used first; or a refusal, when renders hold too much.
  struct Choice {
    bool refused = false;
    std::vector<JournalRecord> models;
  };

  // Renames the written model (its temporary folder) into place in one
  // pass, with the evictions the bound needs first.
  PutResult land(const std::filesystem::path& temp, ModelInfo info, std::uint64_t bytes);
  // The least recently used models no render holds, as many as `incoming`
  // more bytes need to fit under the bound; their last uses checked on the
  // volume first (renders stamp their models' folders, not the index).
  Choice choose(StoreCatalog::Pass& pass, std::uint64_t incoming);
  // Renames the chosen models out, unless a render took one meanwhile;
  // appends their folders (to delete once the pass is over) and ids.
  void let_go(StoreCatalog::Pass& pass, const Choice& choice, std::vector<std::filesystem::path>& doomed,
              std::vector<std::string>& evicted);
  // Whether a render holds the model: a pin here, a lease anywhere. Called
  // with pins_mutex_ held.
  bool held(const std::string& id) const;
  // Renames the model out of place; the folder to delete then, or nothing
  // when the model is not there. Durable once the pass settles.
  std::optional<std::filesystem::path> take_out(const std::string& id);
  // Writes the model's folder under a temporary name; its path.
  std::filesystem::path write_temp(const std::string& id, const Bundle& bundle, const std::string& info_text);
  void checkpoint(std::string_view moment) const;

  std::filesystem::path root_;
  StoreOptions options_;
  std::string holder_;            // this process's name in the lease folders
  mutable StoreCatalog catalog_;  // usage() reads other replicas' changes
  std::mutex pins_mutex_;
  std::unordered_map<std::string, int> pins_;
  std::unordered_map<std::string, int> leases_;
  std::atomic<std::uint64_t> evictions_{0};
  FolderSweeper sweeper_;  // last: its thread deletes before the rest goes
};

}  // namespace toond::scene
