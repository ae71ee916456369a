#include "scene/store/store_catalog.h"

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <utility>

#include "scene/store/durable_files.h"
#include "scene/store/store_error.h"

namespace toond::scene {
namespace fs = std::filesystem;
namespace {

// A rewrite costs a write of every model's record: it waits until the
// journal holds twice as many records as models and this many more, so
// that it comes at most once per as many changes as there are models.
constexpr std::size_t kJournalSlack = 4096;
// How long usage() (for /healthz and /metrics) waits for a pass to end
// before it answers with what this replica last read.
constexpr std::chrono::milliseconds kUsageWait{1000};

StoreError busy(std::chrono::milliseconds waited) {
  return StoreError(StoreError::Kind::Busy,
                    "another replica has held the model store's lock for " + std::to_string(waited.count()) + " ms");
}

fs::path beside(const fs::path& root, const std::string& extension) {
  return root.parent_path() / (root.filename().string() + extension);
}

}  // namespace

StoreCatalog::StoreCatalog(fs::path root, std::chrono::milliseconds lock_wait, Log log)
    : root_(std::move(root)),
      lock_wait_(lock_wait),
      log_(std::move(log)),
      lock_(beside(root_, ".lock")),
      journal_(beside(root_, ".index")) {
  // The first pass reads the index, or builds it.
  Pass opening = pass();
}

StoreCatalog::Pass StoreCatalog::pass() {
  std::unique_lock guard(mutex_, std::defer_lock);
  const auto started = std::chrono::steady_clock::now();
  if (!guard.try_lock_for(lock_wait_)) throw busy(lock_wait_);
  const auto left =
      lock_wait_ - std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started);
  try {
    if (!lock_.lock(std::max(left, std::chrono::milliseconds(0)))) throw busy(lock_wait_);
  } catch (const std::system_error& e) {
    throw_store_failure(e, "the model store could not be locked");
  }
  try {
    catch_up();
  } catch (const std::system_error& e) {
    lock_.unlock();
    throw_store_failure(e, "the model store's index could not be read");
  } catch (...) {
    lock_.unlock();
    throw;
  }
  guard.release();
  return Pass(*this);
}

StoreUsage StoreCatalog::usage() {
  std::unique_lock guard(mutex_, std::defer_lock);
  const auto wait = std::min(lock_wait_, kUsageWait);
  if (guard.try_lock_for(wait)) {
    try {
      if (lock_.lock(wait)) {
        try {
          catch_up();
          compact_when_due();
        } catch (const std::exception&) {
          // What was read before still counts.
        }
        lock_.unlock();
      }
    } catch (const std::exception&) {
    }
    const std::lock_guard seen_lock(seen_mutex_);
    seen_ = index_.usage();
  }
  const std::lock_guard seen_lock(seen_mutex_);
  return seen_;
}

void StoreCatalog::catch_up() {
  StoreJournal::News news = journal_.read();
  if (news.state == StoreJournal::News::State::Missing) {
    rebuild("no index at " + journal_.path().string(), false);
    return;
  }
  if (news.state == StoreJournal::News::State::Damaged) {
    rebuild("the index " + journal_.path().string() + " is damaged (" + news.why + ")", true);
    return;
  }
  if (news.whole) {
    index_.clear();
    unsettled_.clear();
  }
  for (const JournalRecord& record : news.records) apply(record);
  // Any intent still open was left by a replica that died mid-pass: a
  // live one settles its own before it lets go of the lock.
  settle();
}

void StoreCatalog::rebuild(const std::string& why, bool damaged) {
  const auto started = std::chrono::steady_clock::now();
  index_.clear();
  unsettled_.clear();
  for (const StoredModel& m : walk_store(root_)) index_.put(m.id, m.bytes, m.last_use);
  std::vector<JournalRecord> records;
  for (const StoredModel& m : index_.models()) {
    records.push_back({JournalRecord::Kind::Present, m.id, m.bytes, m.last_use});
  }
  journal_.rewrite(records);
  // A new store has no index yet, nothing to build one from, and nothing
  // to say.
  if (records.empty() && !damaged) return;
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - started;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.2f", took.count());
  log_("model store: " + why + "; rebuilt it from the " + std::to_string(records.size()) + " models in " +
       root_.string() + " in " + seconds + " s");
}

void StoreCatalog::settle() {
  if (unsettled_.empty()) return;
  // The renames are on disk before their records are: a crash then never
  // leaves a record of a rename it undid.
  fsync_dir(root_);
  std::vector<JournalRecord> records;
  for (const auto& [id, intent] : unsettled_) {
    const fs::path dir = root_ / id;
    if (const std::optional<std::timespec> used = last_use(dir)) {
      const std::uint64_t bytes = intent.bytes > 0 ? intent.bytes : model_bytes(dir).value_or(0);
      records.push_back({JournalRecord::Kind::Present, id, bytes, *used});
    } else {
      records.push_back({JournalRecord::Kind::Absent, id, 0, {}});
    }
  }
  journal_.append(records, false);
  for (const JournalRecord& record : records) apply(record);
}

void StoreCatalog::apply(const JournalRecord& record) {
  switch (record.kind) {
    case JournalRecord::Kind::Present:
      index_.put(record.id, record.bytes, record.last_use);
      unsettled_.erase(record.id);
      break;
    case JournalRecord::Kind::Absent:
      index_.erase(record.id);
      unsettled_.erase(record.id);
      break;
    case JournalRecord::Kind::Intent:
      unsettled_[record.id] = record;
      break;
  }
}

void StoreCatalog::compact_when_due() {
  if (!unsettled_.empty() || journal_.records() <= 2 * index_.usage().models + kJournalSlack) return;
  std::vector<JournalRecord> records;
  for (const StoredModel& m : index_.models()) {
    records.push_back({JournalRecord::Kind::Present, m.id, m.bytes, m.last_use});
  }
  journal_.rewrite(records);
}

StoreCatalog::Pass::Pass(Pass&& other) noexcept : catalog_(std::exchange(other.catalog_, nullptr)) {}

StoreCatalog::Pass::~Pass() {
  if (catalog_ == nullptr) return;
  try {
    catalog_->settle();
    catalog_->compact_when_due();
  } catch (const std::exception&) {
    // Left unsettled: the next pass, here or on another replica, settles it.
  }
  {
    const std::lock_guard seen_lock(catalog_->seen_mutex_);
    catalog_->seen_ = catalog_->index_.usage();
  }
  catalog_->lock_.unlock();
  catalog_->mutex_.unlock();
}

void StoreCatalog::Pass::intend(const std::vector<JournalRecord>& intents) {
  try {
    catalog_->journal_.append(intents, true);
  } catch (const std::system_error& e) {
    throw_store_failure(e, "the model store's index could not be written");
  }
  for (const JournalRecord& intent : intents) catalog_->apply(intent);
}

void StoreCatalog::Pass::left(const std::string& id) { catalog_->index_.erase(id); }

StoreIndex::Order::const_iterator StoreCatalog::Pass::restamp(const std::string& id, const std::timespec& last_use) {
  return catalog_->index_.restamp(id, last_use);
}

void StoreCatalog::Pass::forget(const std::string& id) {
  catalog_->unsettled_[id] = {JournalRecord::Kind::Intent, id, catalog_->index_.bytes(id), {}};
  catalog_->index_.erase(id);
}

void StoreCatalog::Pass::settle() {
  try {
    catalog_->settle();
  } catch (const std::exception&) {
    // The renames are done and their intents on disk: the next pass, here
    // or on another replica, records them (a full volume may have room by
    // then). The upload or deletion itself succeeded.
  }
}

}  // namespace toond::scene
