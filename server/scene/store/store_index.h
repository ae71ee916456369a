#pragma once
// The store's models in memory: each one's size and last use as the index
// last learnt them, the sum of their sizes, and their order from the least
// recently used. Every change costs O(log n) in the number of models, so
// an upload or an eviction never walks the store. Not thread-safe: the
// store's catalog (scene/store/store_catalog.h) guards it.
#include <cstdint>
#include <ctime>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "scene/store/store_scan.h"

namespace toond::scene {

class StoreIndex {
 public:
  // A model's place in the order: its last use, then its id (models used
  // in the same nanosecond).
  struct Key {
    std::timespec last_use{};
    std::string id;
    bool operator<(const Key& other) const;
  };
  using Order = std::set<Key>;

  // Adds the model, or replaces what was known of it.
  void put(const std::string& id, std::uint64_t bytes, const std::timespec& last_use);
  void erase(const std::string& id);
  // Moves an indexed model to its place for a new last use; that place.
  Order::const_iterator restamp(const std::string& id, const std::timespec& last_use);
  void clear();

  bool contains(const std::string& id) const { return models_.count(id) > 0; }
  // The model's bytes; 0 when it is not indexed.
  std::uint64_t bytes(const std::string& id) const;
  StoreUsage usage() const { return {models_.size(), bytes_}; }
  // Least recently used first. Iterators stay valid across put, erase and
  // restamp of other models.
  const Order& order() const { return order_; }
  // Every model, least recently used first.
  std::vector<StoredModel> models() const;

 private:
  struct Entry {
    std::uint64_t bytes = 0;
    Order::iterator place;
  };
  std::unordered_map<std::string, Entry> models_;
  Order order_;
  std::uint64_t bytes_ = 0;
};

}  // namespace toond::scene
