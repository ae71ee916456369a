#include "scene/store/model_library.h"

#include <algorithm>

#include "bundle_paths/bundle_path.h"
#include "scene/import/bundle_import.h"
#include "scene/import/demo_model.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/crease_edges.h"
#include "scene/mesh/intersection_lines.h"
#include "scene/reading/image_lookup.h"
#include "scene/reading/texture_decode.h"

namespace toond::scene {
namespace {

// Adds `value` under `key` unless another thread got there first (both
// imported outside the lock), newest first in `order`; the least recently
// used beyond `capacity` leave.
template <class Map>
void insert_bounded(Map& map, std::list<std::string>& order, const std::string& key,
                    const typename Map::mapped_type& value, std::size_t capacity) {
  if (map.count(key)) return;
  map.emplace(key, value);
  order.push_front(key);
  while (order.size() > capacity) {
    map.erase(order.back());
    order.pop_back();
  }
}

// The built-in demo model, with the crease edges its box's crease lines
// are drawn along (scene/mesh/crease_edges.h) and the segments where its sphere
// sinks into the box (scene/mesh/intersection_lines.h).
scene::Model demo_with_crease_edges() {
  scene::Model demo = scene::import_obj_bundle(scene::make_demo_bundle());
  scene::find_crease_edges(demo.mesh);
  scene::find_intersection_lines(demo.mesh);
  return demo;
}

}  // namespace

ModelLibrary::ModelLibrary(scene::ModelStore& store, std::size_t capacity)
    : store_(store), capacity_(capacity), demo_(std::make_shared<const scene::Model>(demo_with_crease_edges())) {}

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
  const std::optional<scene::ModelInfo> stored = store_.info(id);
  if (!bundle || !stored) return nullptr;
  auto model = std::make_shared<const scene::Model>(scene::import_bundle(*bundle, {}, stored->choices));
  std::lock_guard lock(mutex_);
  insert_bounded(models_, order_, id, model, capacity_);
  return model;
}

std::shared_ptr<const scene::Model> ModelLibrary::get(const std::string& id, scene::ModelPins& pins) {
  pins.add(id);
  return get(id);
}

void ModelLibrary::forget(const std::string& id) {
  std::lock_guard lock(mutex_);
  models_.erase(id);
  order_.remove(id);
  for (auto it = image_order_.begin(); it != image_order_.end();) {
    if (it->compare(0, id.size() + 1, id + '\n') == 0) {
      images_.erase(*it);
      it = image_order_.erase(it);
    } else {
      ++it;
    }
  }
}

std::shared_ptr<const scene::Texture> ModelLibrary::bundle_image(const std::string& model_key,
                                                                 const std::string& path) {
  // Few distinct images serve many renders (one ramp, one floor per look).
  constexpr std::size_t image_capacity = 32;
  const std::string key = model_key + '\n' + path;
  {
    std::lock_guard lock(mutex_);
    if (auto it = images_.find(key); it != images_.end()) {
      image_order_.remove(key);
      image_order_.push_front(key);
      return it->second;
    }
  }
  const std::optional<scene::Bundle> bundle =
      model_key == "demo" ? std::optional<scene::Bundle>(scene::make_demo_bundle()) : store_.load(model_key);
  if (!bundle) return nullptr;
  // A request names a bundle path: one that would leave the bundle names
  // nothing, whatever file of its name the bundle holds.
  if (bundle_paths::resolve_reference("", path).refusal != bundle_paths::Refusal::none) return nullptr;
  const std::optional<FoundImage> found = find_image(*bundle, "", path);
  if (!found) return nullptr;
  auto image = std::make_shared<const scene::Texture>(scene::decode_texture(*bundle->find(found->path), found->path));
  std::lock_guard lock(mutex_);
  insert_bounded(images_, image_order_, key, image, image_capacity);
  return image;
}

}  // namespace toond::scene
