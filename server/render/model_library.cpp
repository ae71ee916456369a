#include "render/model_library.h"

#include <algorithm>

#include "scene/demo_model.h"
#include "scene/bundle_import.h"
#include "scene/obj_import.h"

namespace toond::render {

ModelLibrary::ModelLibrary(scene::ModelStore& store, std::size_t capacity)
    : store_(store),
      capacity_(capacity),
      demo_(std::make_shared<const scene::Model>(scene::import_obj_bundle(scene::make_demo_bundle()))) {}

std::shared_ptr<const scene::Model> ModelLibrary::get(const std::string& id) {
  // Replicas share the data directory: a model another replica deleted must
  // stop rendering here too, not live on in this one's memory.
  if (!store_.contains(id)) {
    forget(id);
    return nullptr;
  }
  {
    std::lock_guard lock(mutex_);
    if (auto it = models_.find(id); it != models_.end()) {
      order_.remove(id);
      order_.push_front(id);
      return it->second;
    }
  }
  // Import outside the lock: a large model must not stall other requests.
  std::optional<scene::Bundle> bundle = store_.load(id);
  if (!bundle) return nullptr;
  auto model = std::make_shared<const scene::Model>(scene::import_bundle(*bundle));
  std::lock_guard lock(mutex_);
  if (!models_.count(id)) {
    models_.emplace(id, model);
    order_.push_front(id);
    while (order_.size() > capacity_) {
      models_.erase(order_.back());
      order_.pop_back();
    }
  }
  return model;
}

void ModelLibrary::forget(const std::string& id) {
  std::lock_guard lock(mutex_);
  models_.erase(id);
  order_.remove(id);
}

}  // namespace toond::render
