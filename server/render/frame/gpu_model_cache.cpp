#include "render/frame/gpu_model_cache.h"

#include <algorithm>

namespace toond::render {

GpuModel& GpuModelCache::get(const std::string& key, const scene::Model& model,
                             const std::vector<std::string>& pinned) {
  if (auto it = index_.find(key); it != index_.end()) {
    order_.splice(order_.begin(), order_, it->second);
    return *it->second->second;
  }
  order_.emplace_front(key, std::make_unique<GpuModel>(model));
  index_[key] = order_.begin();
  bytes_ += order_.front().second->gpu_bytes();
  auto victim = order_.end();
  while (over_limits() && victim != order_.begin()) {
    --victim;
    if (victim == order_.begin() || std::find(pinned.begin(), pinned.end(), victim->first) != pinned.end()) {
      continue;
    }
    bytes_ -= victim->second->gpu_bytes();
    index_.erase(victim->first);
    victim = order_.erase(victim);
  }
  return *order_.front().second;
}

void GpuModelCache::forget(const std::string& key) {
  auto it = index_.find(key);
  if (it == index_.end()) return;
  bytes_ -= it->second->second->gpu_bytes();
  order_.erase(it->second);
  index_.erase(it);
}

}  // namespace toond::render
