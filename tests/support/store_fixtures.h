#pragma once
// What the model store's tests share: small distinct models, and the store
// as the volume holds it, read while no replica can change it.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "scene/import/bundle.h"
#include "scene/store/store_scan.h"

namespace toond::test {

// A one-triangle OBJ padded with a comment to about `bytes`; `tag` makes
// it another model.
inline scene::Bundle padded_model(const std::string& tag, std::size_t bytes = 10000) {
  std::string obj = "# " + tag + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# ";
  obj.append(bytes > obj.size() ? bytes - obj.size() : 0, 'x');
  obj += "\n";
  scene::Bundle bundle;
  bundle.add("m.obj", obj);
  return bundle;
}

// Every model folder under DATA/models and its bytes (temporary folders
// left out), walked while holding the store's lock (DATA/models.lock), so
// that no replica's pass is half done meanwhile.
inline std::map<std::string, std::uint64_t> models_on_disk(const std::filesystem::path& data_dir) {
  const int fd = ::open((data_dir / "models.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd >= 0) ::flock(fd, LOCK_EX);
  std::map<std::string, std::uint64_t> models;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir / "models")) {
    const std::string name = entry.path().filename().string();
    if (!scene::is_model_id(name)) continue;
    models[name] = scene::model_bytes(entry.path()).value_or(0);
  }
  if (fd >= 0) ::close(fd);
  return models;
}

inline std::uint64_t total_bytes(const std::map<std::string, std::uint64_t>& models) {
  std::uint64_t bytes = 0;
  for (const auto& [id, size] : models) bytes += size;
  return bytes;
}

}  // namespace toond::test
