#pragma once
// Models uploaded to the GPU, kept for the next render: most recently used
// first, the least recently used dropped when the cache holds more models
// or more GPU bytes than allowed. Render thread only (it owns GL objects).
#include <cstddef>
#include <list>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "render/frame/gpu_model.h"

namespace toond::render {

class GpuModelCache {
 public:
  GpuModelCache(std::size_t max_models, std::size_t max_bytes) : max_models_(max_models), max_bytes_(max_bytes) {}

  // Uploads `model` under `key` unless it is already there. Keys in
  // `pinned` (the current scene's objects) are never evicted, nor is the
  // model just asked for: a scene larger than the limits is held whole
  // until its render is done, and the next load trims the cache back.
  GpuModel& get(const std::string& key, const scene::Model& model, const std::vector<std::string>& pinned = {});
  void forget(const std::string& key);

  std::size_t size() const { return order_.size(); }
  std::size_t bytes() const { return bytes_; }

 private:
  using Entry = std::pair<std::string, std::unique_ptr<GpuModel>>;
  bool over_limits() const { return order_.size() > max_models_ || bytes_ > max_bytes_; }

  std::size_t max_models_;
  std::size_t max_bytes_;
  std::size_t bytes_ = 0;
  std::list<Entry> order_;
  std::unordered_map<std::string, std::list<Entry>::iterator> index_;
};

}  // namespace toond::render
