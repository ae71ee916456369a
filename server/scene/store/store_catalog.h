#pragma once
// The store's index as every replica sharing the data directory keeps it:
// in memory (scene/store/store_index.h), on the volume (DATA/models.index,
// scene/store/store_journal.h), and changed only in a pass that holds the
// store's lock across replicas (DATA/models.lock, scene/store/store_lock.h).
// A pass starts by reading what other replicas wrote since this one's last
// pass and by settling what a replica that died mid-pass left unsettled, so
// each pass sees the store as the volume holds it, and one pass runs at a
// time across uploads and replicas.
//
// The index is read at start; only when it is missing or damaged is it
// rebuilt from a walk of every model, with a log line saying so.
#include <chrono>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/store/store_index.h"
#include "scene/store/store_journal.h"
#include "scene/store/store_lock.h"
#include "scene/store/store_scan.h"

namespace toond::scene {

class StoreCatalog {
 public:
  using Log = std::function<void(const std::string&)>;
  // The index of the models under `root` (DATA/models), kept beside it.
  // Throws StoreError (Busy) when another replica holds the lock past
  // `lock_wait`.
  StoreCatalog(std::filesystem::path root, std::chrono::milliseconds lock_wait, Log log);

  class Pass;
  // The store to this thread alone, across replicas, until the pass ends.
  // Throws StoreError: Busy past `lock_wait`, Failed (or VolumeFull) when
  // the index cannot be read or written.
  Pass pass();

  // Models and bytes as the index has them: every replica's changes, unless
  // another replica holds the lock just now (then as of this replica's last
  // pass). Never throws.
  StoreUsage usage();

 private:
  friend class Pass;
  // Applies what other replicas wrote (or rebuilds the index) and settles
  // what a dead one left. Called with both locks held.
  void catch_up();
  // A walk of every model; `damaged`: there was an index, unreadable.
  void rebuild(const std::string& why, bool damaged);
  // Records what the disk shows of each unsettled model, once the renames
  // are on disk.
  void settle();
  void apply(const JournalRecord& record);
  // Rewrites the journal once it holds many more records than models.
  void compact_when_due();

  std::filesystem::path root_;
  std::chrono::milliseconds lock_wait_;
  Log log_;
  std::timed_mutex mutex_;  // this process's threads, one pass at a time
  StoreLock lock_;          // every replica's
  StoreJournal journal_;
  StoreIndex index_;
  // Intents not yet settled: model → the bytes and last use it comes with.
  std::unordered_map<std::string, JournalRecord> unsettled_;
  // usage() as of the last pass, for when the lock is taken.
  std::mutex seen_mutex_;
  StoreUsage seen_;
};

class StoreCatalog::Pass {
 public:
  Pass(Pass&& other) noexcept;
  Pass(const Pass&) = delete;
  Pass& operator=(const Pass&) = delete;
  Pass& operator=(Pass&&) = delete;
  // Settles what is left (best effort) and lets go of the store.
  ~Pass();

  const StoreIndex& index() const { return catalog_->index_; }
  // Before models are renamed in or out: on disk once it returns.
  void intend(const std::vector<JournalRecord>& intents);
  // A model renamed out in this pass: no longer counted (recorded when the
  // pass settles).
  void left(const std::string& id);
  // A model's last use as its folder shows it, found newer (or older) than
  // the index had it; where that puts it in the order.
  StoreIndex::Order::const_iterator restamp(const std::string& id, const std::timespec& last_use);
  // A model found gone that no intent covers (removed by hand).
  void forget(const std::string& id);
  // Records what the disk shows of every model intended in this pass (its
  // renames made durable first). Best effort: what cannot be recorded now
  // stays an intent, which the next pass settles.
  void settle();

 private:
  friend class StoreCatalog;
  explicit Pass(StoreCatalog& catalog) : catalog_(&catalog) {}
  StoreCatalog* catalog_;
};

}  // namespace toond::scene
