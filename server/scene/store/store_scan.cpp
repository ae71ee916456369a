#include "scene/store/store_scan.h"

#include <sys/stat.h>

#include <algorithm>
#include <system_error>

namespace toond::scene {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kModelIdLength = 32;

}  // namespace

bool is_model_id(std::string_view name) {
  return name.size() == kModelIdLength &&
         std::all_of(name.begin(), name.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

std::optional<std::uint64_t> model_bytes(const fs::path& model_dir) {
  std::error_code ec;
  std::uint64_t bytes = 0;
  for (fs::recursive_directory_iterator it(model_dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code size_ec;
    if (!it->is_regular_file(size_ec)) continue;
    const auto size = it->file_size(size_ec);
    if (!size_ec) bytes += size;
  }
  if (ec) return std::nullopt;
  return bytes;
}

std::optional<std::timespec> last_use(const fs::path& model_dir) {
  struct stat st {};
  if (::stat(model_dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return std::nullopt;
  return st.st_mtim;
}

std::vector<StoredModel> walk_store(const fs::path& root) {
  std::vector<StoredModel> models;
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (!is_model_id(name)) continue;
    const std::optional<std::timespec> used = last_use(it->path());
    if (!used) continue;
    const std::optional<std::uint64_t> bytes = model_bytes(it->path());
    if (!bytes) continue;
    models.push_back({std::move(name), *bytes, *used});
  }
  return models;
}

}  // namespace toond::scene
