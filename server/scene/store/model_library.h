#pragma once
// Imported models kept in memory by id, so a render does not re-read and
// re-import its bundle; imports happen on the HTTP threads, never on the
// render thread. Holds the built-in demo model under the key "demo".
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "scene/mesh/model.h"
#include "scene/store/model_pins.h"
#include "scene/store/model_store.h"

namespace toond::scene {

class ModelLibrary {
 public:
  ModelLibrary(scene::ModelStore& store, std::size_t capacity);

  // The model, imported from the store on first use; nullptr when the store
  // has no such id (or lost it while it was read).
  std::shared_ptr<const scene::Model> get(const std::string& id);
  // The same for a render: the model is pinned in `pins` first, so that
  // once it is found the store does not let it go before the render is
  // answered.
  std::shared_ptr<const scene::Model> get(const std::string& id, scene::ModelPins& pins);
  std::shared_ptr<const scene::Model> demo() const { return demo_; }
  void forget(const std::string& id);

  // An image file of a model's bundle ("demo": the built-in one) decoded
  // as an sRGB colour image, for request parameters that name files
  // (shading.ramp_image, floor.texture); kept for later renders. `path` is
  // resolved inside the bundle only (Bundle::resolve). nullptr when the model
  // or the file does not exist; throws std::runtime_error when the file is
  // not a decodable image.
  std::shared_ptr<const scene::Texture> bundle_image(const std::string& model_key, const std::string& path);

 private:
  scene::ModelStore& store_;
  std::size_t capacity_;
  std::shared_ptr<const scene::Model> demo_;
  std::mutex mutex_;
  std::list<std::string> order_;  // most recent first
  std::unordered_map<std::string, std::shared_ptr<const scene::Model>> models_;
  std::list<std::string> image_order_;  // most recent first
  std::unordered_map<std::string, std::shared_ptr<const scene::Texture>> images_;
};

}  // namespace toond::scene
