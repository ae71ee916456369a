#pragma once
// What the model store holds as the volume shows it, model by model: its
// size and its last use. The store's index (scene/store/store_index.h) is
// built from a walk of the whole store only when it is missing or damaged;
// everything else asks about one model at a time.
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
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

// The bytes of every file under a model's folder; nothing when the folder
// went away while it was counted.
std::optional<std::uint64_t> model_bytes(const std::filesystem::path& model_dir);

// The model's last use; nothing when its folder is not there.
std::optional<std::timespec> last_use(const std::filesystem::path& model_dir);

// Every model under `root` (folders named as ids), in no order; models
// gone meanwhile are left out.
std::vector<StoredModel> walk_store(const std::filesystem::path& root);

// Models and bytes in the store.
struct StoreUsage {
  std::size_t models = 0;
  std::uint64_t bytes = 0;
};

}  // namespace toond::scene
