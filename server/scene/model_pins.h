#pragma once
// The stored models one request renders, pinned in the store
// (ModelStore::pin) until the request is answered: from the moment it takes
// a model until its image is sent, no replica lets the model go.
#include <string>
#include <vector>

#include "scene/model_store.h"

namespace toond::scene {

class ModelPins {
 public:
  explicit ModelPins(ModelStore& store) : store_(store) {}
  ~ModelPins() {
    for (const std::string& id : ids_) store_.unpin(id);
  }
  ModelPins(const ModelPins&) = delete;
  ModelPins& operator=(const ModelPins&) = delete;

  void add(const std::string& id) {
    store_.pin(id);
    ids_.push_back(id);
  }

 private:
  ModelStore& store_;
  std::vector<std::string> ids_;
};

}  // namespace toond::scene
