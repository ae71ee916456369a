#pragma once
// A count per mesh edge, keyed by the edge's two position groups packed in
// one 64-bit number (the smaller id in the high half). Open addressing in
// one flat array: the node-based map it replaces cost an allocation per
// edge, and its scattered nodes made large imports slower than linear.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace toond::scene {

class EdgeTable {
 public:
  // Room for `expected` edges before the table first grows.
  explicit EdgeTable(std::size_t expected = 0) { resize(expected); }

  // The edge between groups a and b, either way round.
  static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    const auto [lo, hi] = std::minmax(a, b);
    return static_cast<std::uint64_t>(lo) << 32 | hi;
  }

  // The count of `edge`, made 0 if it is new.
  int& operator[](std::uint64_t edge) {
    if (2 * (used_ + 1) > slots_.size()) resize(2 * used_ + 2);
    Slot& slot = slots_[find(edge)];
    if (slot.key == kEmpty) {
      slot.key = edge;
      ++used_;
    }
    return slot.count;
  }

  // The count of `edge`, 0 if it was never counted.
  int get(std::uint64_t edge) const {
    const Slot& slot = slots_[find(edge)];
    return slot.key == kEmpty ? 0 : slot.count;
  }

  // fn(edge, count) for every edge counted, in no particular order.
  template <class Fn>
  void for_each(Fn&& fn) const {
    for (const Slot& slot : slots_) {
      if (slot.key != kEmpty) fn(slot.key, slot.count);
    }
  }

  std::size_t size() const { return used_; }

 private:
  // Group ids are below 2^32 - 1, so no edge packs to this.
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  struct Slot {
    std::uint64_t key = kEmpty;
    int count = 0;
  };

  std::size_t find(std::uint64_t edge) const {
    const std::size_t mask = slots_.size() - 1;
    // Fibonacci hashing spreads the packed ids, whose low bits alone would
    // cluster (neighbouring edges share a high half).
    std::size_t i = static_cast<std::size_t>((edge * 0x9E3779B97F4A7C15ull) >> 17) & mask;
    while (slots_[i].key != kEmpty && slots_[i].key != edge) i = (i + 1) & mask;
    return i;
  }

  void resize(std::size_t expected) {
    std::size_t size = 16;
    while (size < 2 * expected) size *= 2;
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(size, Slot{});
    used_ = 0;
    for (const Slot& slot : old) {
      if (slot.key == kEmpty) continue;
      slots_[find(slot.key)] = slot;
      ++used_;
    }
  }

  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

}  // namespace toond::scene
