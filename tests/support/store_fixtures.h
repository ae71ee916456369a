#pragma once
// What the model store's tests share: small distinct models, and the store
// as the volume holds it, read while no replica can change it.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "scene/import/bundle_import.h"
#include "scene/reading/bundle.h"
#include "scene/store/model_store.h"
#include "scene/store/model_use.h"
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

// The id the store gives a bundle uploaded with no choices.
inline std::string stored_id(const scene::Bundle& bundle) {
  return scene::bundle_id(bundle, scene::with_format_up(bundle, {}));
}

// `n` padded models of about `bytes` ("stored-0", "stored-1", …, the oldest
// first, a second apart) written straight into DATA/models as the store
// lays models out, each with the info.json a real upload of one wrote: a
// large store made in seconds, without an import or an fsync per model.
// The store's index is left to be built when a store next opens. Without
// `files`, each model is its folder and info.json alone: what letting it go
// and counting it need, in fewer files to write and delete.
inline void fill_store(const std::filesystem::path& data_dir, std::size_t n, std::size_t bytes, bool files = true) {
  namespace fs = std::filesystem;
  scene::ModelInfo info;
  const fs::path seed_dir = data_dir / "seed";
  {
    scene::StoreOptions quiet;
    quiet.log = [](const std::string&) {};
    scene::ModelStore seed(seed_dir, quiet);
    info = seed.put(padded_model("seed", bytes)).info;
  }
  fs::remove_all(seed_dir);
  const fs::path root = data_dir / "models";
  fs::create_directories(root);
  const std::timespec now = scene::wall_clock_now();
  for (std::size_t i = 0; i < n; ++i) {
    const scene::Bundle bundle = padded_model("stored-" + std::to_string(i), bytes);
    info.id = stored_id(bundle);
    const fs::path dir = root / info.id;
    fs::create_directory(dir);
    if (files) {
      fs::create_directory(dir / "files");
      fs::create_directory(dir / scene::kLeaseFolder);
      std::ofstream(dir / "files" / "m.obj", std::ios::binary) << *bundle.find("m.obj");
    }
    std::ofstream(dir / "info.json", std::ios::binary) << info.to_json().dump(2) << "\n";
    scene::stamp_use(dir, {now.tv_sec - static_cast<std::time_t>(n - i), 0});
  }
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
