#include "pipeline/result_cache.h"

#include <cstdint>
#include <cstdio>

namespace toond::pipeline {

std::string etag_of(const std::string& body) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : body) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[24];
  std::snprintf(buf, sizeof buf, "\"%016llx\"", static_cast<unsigned long long>(h));
  return buf;
}

std::size_t ResultCache::cost(const std::string& key, const CachedRender& r) {
  // The strings' contents dominate; a fixed allowance covers the nodes.
  return key.size() + r.body.size() + r.etag.size() + r.passes.size() + r.lod.size() + 256;
}

std::shared_ptr<const CachedRender> ResultCache::find(const std::string& key) {
  std::lock_guard lock(mutex_);
  const auto it = index_.find(key);
  if (it == index_.end()) {
    ++misses_;
    return nullptr;
  }
  ++hits_;
  lru_.splice(lru_.begin(), lru_, it->second);
  return it->second->render;
}

void ResultCache::put(const std::string& key, std::shared_ptr<const CachedRender> render) {
  if (!render) return;
  const std::size_t size = cost(key, *render);
  std::lock_guard lock(mutex_);
  if (size > capacity_) return;
  if (const auto it = index_.find(key); it != index_.end()) {
    bytes_ -= it->second->bytes;
    lru_.erase(it->second);
    index_.erase(it);
  }
  while (bytes_ + size > capacity_ && !lru_.empty()) {
    bytes_ -= lru_.back().bytes;
    index_.erase(lru_.back().key);
    lru_.pop_back();
  }
  lru_.push_front({key, std::move(render), size});
  index_[key] = lru_.begin();
  bytes_ += size;
}

std::size_t ResultCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}
std::size_t ResultCache::entries() const {
  std::lock_guard lock(mutex_);
  return lru_.size();
}
std::size_t ResultCache::hits() const {
  std::lock_guard lock(mutex_);
  return hits_;
}
std::size_t ResultCache::misses() const {
  std::lock_guard lock(mutex_);
  return misses_;
}

}  // namespace toond::pipeline
