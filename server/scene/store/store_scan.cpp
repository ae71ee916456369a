#include "scene/store/store_scan.h"

#include <sys/stat.h>

#include <algorithm>
#include <optional>
#include <system_error>
#include <tuple>
#include <unordered_set>

namespace toond::scene {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kModelIdLength = 32;

// The bytes of every file under a model's folder; nothing when the folder
// went away while it was counted.
std::optional<std::uint64_t> folder_bytes(const fs::path& dir) {
  std::error_code ec;
  std::uint64_t bytes = 0;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code size_ec;
    if (!it->is_regular_file(size_ec)) continue;
    const auto size = it->file_size(size_ec);
    if (!size_ec) bytes += size;
  }
  if (ec) return std::nullopt;
  return bytes;
}

}  // namespace

bool is_model_id(std::string_view name) {
  return name.size() == kModelIdLength &&
         std::all_of(name.begin(), name.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

void sort_least_recently_used(std::vector<StoredModel>& models) {
  std::sort(models.begin(), models.end(), [](const StoredModel& a, const StoredModel& b) {
    return std::tie(a.last_use.tv_sec, a.last_use.tv_nsec, a.id) <
           std::tie(b.last_use.tv_sec, b.last_use.tv_nsec, b.id);
  });
}

std::vector<StoredModel> ModelSizes::scan(const fs::path& root) {
  std::vector<StoredModel> models;
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    struct stat st {};
    if (!is_model_id(name) || ::stat(it->path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) continue;
    StoredModel model{std::move(name), 0, st.st_mtim};
    {
      std::lock_guard lock(mutex_);
      if (const auto known = bytes_.find(model.id); known != bytes_.end()) model.bytes = known->second;
    }
    if (model.bytes == 0) {
      const std::optional<std::uint64_t> bytes = folder_bytes(it->path());
      if (!bytes) continue;
      model.bytes = *bytes;
      std::lock_guard lock(mutex_);
      bytes_[model.id] = *bytes;
    }
    models.push_back(std::move(model));
  }
  std::unordered_set<std::string> present;
  for (const StoredModel& m : models) present.insert(m.id);
  {
    std::lock_guard lock(mutex_);
    std::erase_if(bytes_, [&](const auto& entry) { return !present.count(entry.first); });
  }
  sort_least_recently_used(models);
  return models;
}

void ModelSizes::forget(const std::string& id) {
  std::lock_guard lock(mutex_);
  bytes_.erase(id);
}

StoreUsage add_up(const std::vector<StoredModel>& models) {
  StoreUsage usage;
  for (const StoredModel& m : models) {
    ++usage.models;
    usage.bytes += m.bytes;
  }
  return usage;
}

}  // namespace toond::scene
