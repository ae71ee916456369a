#pragma once
// Imported models kept in memory by id, so a render does not re-read and
// re-import its bundle; imports happen on the HTTP threads, never on the
// render thread. Holds the built-in demo model under the key "demo".
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "scene/model.h"
#include "scene/model_store.h"

namespace toond::render {

class ModelLibrary {
 public:
  ModelLibrary(scene::ModelStore& store, std::size_t capacity);

  // The model, imported from the store on first use; nullptr when the store
  // has no such id.
  std::shared_ptr<const scene::Model> get(const std::string& id);
  std::shared_ptr<const scene::Model> demo() const { return demo_; }
  void forget(const std::string& id);

 private:
  scene::ModelStore& store_;
  std::size_t capacity_;
  std::shared_ptr<const scene::Model> demo_;
  std::mutex mutex_;
  std::list<std::string> order_;  // most recent first
  std::unordered_map<std::string, std::shared_ptr<const scene::Model>> models_;
};

}  // namespace toond::render
