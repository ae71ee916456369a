#pragma once
// An insert-only hash map in two flat arrays: the entries in the order they
// were added, and an open-addressing index into them (linear probing, at
// most half full). The import's tables hold an entry per vertex, corner or
// triangle of the model; a node-based std::unordered_map cost an allocation
// per entry and scattered the entries over the heap, which made a large
// import slower than linear.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace toond::scene {

// `Hash` may be weak (the identity of an integer will do): its value is
// spread by Fibonacci hashing before it picks a slot.
template <class Key, class Value, class Hash>
class FlatMap {
 public:
  // Room for `expected` entries before the index first grows.
  explicit FlatMap(std::size_t expected = 0) {
    entries_.reserve(expected);
    rehash(expected);
  }

  // The value under `key`, made a copy of `value` when the key is new, and
  // whether it is new. The reference holds until the next insertion.
  std::pair<Value&, bool> try_emplace(const Key& key, const Value& value) {
    if (2 * (entries_.size() + 1) > index_.size()) rehash(2 * entries_.size() + 2);
    std::uint32_t& slot = index_[slot_of(key)];
    if (slot != kEmpty) return {entries_[slot].second, false};
    slot = static_cast<std::uint32_t>(entries_.size());
    entries_.emplace_back(key, value);
    return {entries_.back().second, true};
  }

  // The value under `key`, or null when it was never added.
  const Value* find(const Key& key) const {
    const std::uint32_t slot = index_[slot_of(key)];
    return slot == kEmpty ? nullptr : &entries_[slot].second;
  }

  std::size_t size() const { return entries_.size(); }

 private:
  static constexpr std::uint32_t kEmpty = ~0u;

  std::size_t home_of(const Key& key) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(Hash{}(key)) * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  // The slot that holds `key`, or the empty one where it would go.
  std::size_t slot_of(const Key& key) const {
    const std::size_t mask = index_.size() - 1;
    std::size_t i = home_of(key);
    while (index_[i] != kEmpty && !(entries_[index_[i]].first == key)) i = (i + 1) & mask;
    return i;
  }

  void rehash(std::size_t expected) {
    int bits = 4;
    while ((std::size_t{1} << bits) < 2 * expected) ++bits;
    index_.assign(std::size_t{1} << bits, kEmpty);
    shift_ = 64 - bits;
    const std::size_t mask = index_.size() - 1;
    for (std::size_t e = 0; e < entries_.size(); ++e) {
      std::size_t i = home_of(entries_[e].first);
      while (index_[i] != kEmpty) i = (i + 1) & mask;
      index_[i] = static_cast<std::uint32_t>(e);
    }
  }

  std::vector<std::pair<Key, Value>> entries_;
  std::vector<std::uint32_t> index_;
  int shift_ = 60;
};

}  // namespace toond::scene
