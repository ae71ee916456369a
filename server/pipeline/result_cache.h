#pragma once
// Finished renders kept in memory, keyed by what fully decides the image:
// the canonical (preset-expanded, default-completed) parameters, which name
// the content-addressed models. An identical request is answered from here
// without touching the render thread. Bounded by bytes, least recently used
// out first; thread-safe. The pipeline's entry (render_entry.h) owns it.
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "pipeline/streamed_body.h"

namespace toond::pipeline {

struct CachedRender {
  std::string body;  // the image: a PNG, or what content_type says
  std::string content_type = "image/png";
  std::string etag;    // strong validator of `body`, quoted: "\"…\""
  std::string passes;  // X-Toond-Passes of the render that made it
  std::string lod;     // X-Toond-Lod of the render that made it
  int samples = 1;     // X-Toond-Samples: MSAA samples the render had
  // Headers that belong to this output alone (a depth layer's range).
  std::vector<std::pair<std::string, std::string>> headers{};
  // Set: `body` is empty and is written as the answer goes out (a large
  // line drawing); such a render has no `etag` and is not kept.
  std::shared_ptr<const StreamedBody> stream{};
};

// A strong ETag for a body: its 64-bit FNV-1a hash, quoted. The same bytes
// get the same tag on every replica.
std::string etag_of(const std::string& body);

class ResultCache {
 public:
  // 0 bytes: caches nothing.
  explicit ResultCache(std::size_t capacity_bytes) : capacity_(capacity_bytes) {}

  std::shared_ptr<const CachedRender> find(const std::string& key);
  // Keeps `render` unless it alone is larger than the whole cache.
  void put(const std::string& key, std::shared_ptr<const CachedRender> render);

  std::size_t capacity_bytes() const { return capacity_; }
  std::size_t bytes() const;
  std::size_t entries() const;
  std::size_t hits() const;
  std::size_t misses() const;

 private:
  struct Entry {
    std::string key;
    std::shared_ptr<const CachedRender> render;
    std::size_t bytes;
  };
  static std::size_t cost(const std::string& key, const CachedRender& r);

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::list<Entry> lru_;  // most recently used first
  std::unordered_map<std::string, std::list<Entry>::iterator> index_;
  std::size_t bytes_ = 0;
  std::size_t hits_ = 0;
  std::size_t misses_ = 0;
};

}  // namespace toond::pipeline
