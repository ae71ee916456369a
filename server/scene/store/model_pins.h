#pragma once
// The stored models one render request uses, held in the store until the
// request is answered: pinned from the moment it looks them up (this
// process lets none of them go), and leased from the moment its render is
// queued (no replica sharing the volume lets them go). A request answered
// from the result cache never queues a render and takes no lease.
#include <string>
#include <vector>

#include "scene/store/model_store.h"

namespace toond::scene {

class ModelPins {
 public:
  explicit ModelPins(ModelStore& store) : store_(store) {}
  ~ModelPins() {
    for (const std::string& id : ids_) {
      if (leased_) store_.unlease(id);
      store_.unpin(id);
    }
  }
  ModelPins(const ModelPins&) = delete;
  ModelPins& operator=(const ModelPins&) = delete;

  void add(const std::string& id) {
    store_.pin(id);
    if (leased_) store_.lease(id);
    ids_.push_back(id);
  }
  // The render is about to be queued.
  void lease() {
    if (leased_) return;
    for (const std::string& id : ids_) store_.lease(id);
    leased_ = true;
  }

 private:
  ModelStore& store_;
  std::vector<std::string> ids_;
  bool leased_ = false;
};

}  // namespace toond::scene
