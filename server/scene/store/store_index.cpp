#include "scene/store/store_index.h"

#include <tuple>

namespace toond::scene {

bool StoreIndex::Key::operator<(const Key& other) const {
  return std::tie(last_use.tv_sec, last_use.tv_nsec, id) <
         std::tie(other.last_use.tv_sec, other.last_use.tv_nsec, other.id);
}

void StoreIndex::put(const std::string& id, std::uint64_t bytes, const std::timespec& last_use) {
  erase(id);
  const auto place = order_.insert(Key{last_use, id}).first;
  models_.emplace(id, Entry{bytes, place});
  bytes_ += bytes;
}

void StoreIndex::erase(const std::string& id) {
  const auto it = models_.find(id);
  if (it == models_.end()) return;
  bytes_ -= it->second.bytes;
  order_.erase(it->second.place);
  models_.erase(it);
}

StoreIndex::Order::const_iterator StoreIndex::restamp(const std::string& id, const std::timespec& last_use) {
  Entry& entry = models_.at(id);
  order_.erase(entry.place);
  entry.place = order_.insert(Key{last_use, id}).first;
  return entry.place;
}

void StoreIndex::clear() {
  models_.clear();
  order_.clear();
  bytes_ = 0;
}

std::uint64_t StoreIndex::bytes(const std::string& id) const {
  const auto it = models_.find(id);
  return it == models_.end() ? 0 : it->second.bytes;
}

std::vector<StoredModel> StoreIndex::models() const {
  std::vector<StoredModel> models;
  models.reserve(order_.size());
  for (const Key& key : order_) models.push_back({key.id, models_.at(key.id).bytes, key.last_use});
  return models;
}

}  // namespace toond::scene
