#pragma once
// What the model store tests share: distinct uploads of one real file, and
// the store as the disk holds it.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <thread>

#include <httplib.h>

#include "support/shared_models.h"

namespace toond::test {

// The Utah teapot (206 KiB of OBJ, no normals) uploaded with another
// ?smooth_angle is another model with an id of its own: as many distinct
// uploads of one real file as there are angles.
inline httplib::Result upload_teapot(httplib::Client& client, int smooth_angle) {
  static const std::string obj = read_file(shared_models_dir() / "utah-teapot" / "teapot.obj");
  httplib::MultipartFormDataItems items{{"file", obj, "teapot.obj", "text/plain"}};
  return client.Post(("/models?smooth_angle=" + std::to_string(smooth_angle)).c_str(), items);
}

// The folders under DATA/models: model ids, and any temporary (".tmp-")
// folder an upload or a removal left.
inline std::set<std::string> store_entries(const std::filesystem::path& data_dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(data_dir / "models")) {
    names.insert(e.path().filename().string());
  }
  return names;
}

// The same once no temporary folder is left, waiting 5 s at most: each
// replica deletes the models it let go on a thread of its own, just after
// the upload that let them go is answered.
inline std::set<std::string> store_entries_once_swept(const std::filesystem::path& data_dir) {
  std::set<std::string> names = store_entries(data_dir);
  const auto temporary = [&] {
    return std::any_of(names.begin(), names.end(), [](const std::string& n) { return n.starts_with(".tmp-"); });
  };
  for (int tries = 0; tries < 500 && temporary(); ++tries) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    names = store_entries(data_dir);
  }
  return names;
}

// The bytes of the stored models' files, as `du --apparent-size` counts
// files (temporary folders left out).
inline std::uint64_t stored_file_bytes(const std::filesystem::path& data_dir) {
  std::uint64_t bytes = 0;
  for (const auto& model : std::filesystem::directory_iterator(data_dir / "models")) {
    if (model.path().filename().string().starts_with(".tmp-")) continue;
    for (const auto& e : std::filesystem::recursive_directory_iterator(model.path())) {
      if (e.is_regular_file()) bytes += e.file_size();
    }
  }
  return bytes;
}

}  // namespace toond::test
