#pragma once
// What the model store holds, model by model: its size and its last use,
// read from the shared data directory, so that every replica counts the
// models every other one stored. The order eviction takes them in.
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace toond::scene {

// Whether a name has the exact shape of the ids the store hands out (ids
// arrive from URLs: nothing else may touch the disk).
bool is_model_id(std::string_view name);

struct StoredModel {
  std::string id;
  std::uint64_t bytes = 0;   // its files and info.json, as their sizes say
  std::timespec last_use{};  // its folder's modification time (scene/store/model_use.h)
};

// Least recently used first; models used in the same nanosecond by id.
void sort_least_recently_used(std::vector<StoredModel>& models);

// Sizes of stored models, measured once per id: a model's files never
// change under its id, which is a hash of them. Thread-safe.
class ModelSizes {
 public:
  // Every model under `root` (folders named as ids), least recently used
  // first; models gone meanwhile are left out and their sizes forgotten.
  std::vector<StoredModel> scan(const std::filesystem::path& root);
  void forget(const std::string& id);

 private:
  std::mutex mutex_;
  std::unordered_map<std::string, std::uint64_t> bytes_;
};

// What scan() found, added up.
struct StoreUsage {
  std::size_t models = 0;
  std::uint64_t bytes = 0;
};
StoreUsage add_up(const std::vector<StoredModel>& models);

}  // namespace toond::scene
