#pragma once
// A set of at most 256 RGBA colours, each with the index it was added
// under: the lookup behind exact palettes. Open addressing over four times
// more slots than colours, so a probe rarely goes past its first slot, and
// small enough (6 KiB) to stay in L1 while a frame is scanned.
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace toond::image {

// A pixel's four bytes as one word, in memory order.
inline std::uint32_t load_rgba(const std::uint8_t* pixel) {
  std::uint32_t packed;
  std::memcpy(&packed, pixel, 4);
  return packed;
}

class ColourTable {
 public:
  static constexpr int kCapacity = 256;

  // The colour's index, adding it as the next one if unseen; -1 when it is
  // unseen and the table is full.
  int index_of(std::uint32_t colour) {
    for (std::uint32_t slot = hash(colour);; slot = (slot + 1) & kMask) {
      if (index_[slot] < 0) {
        if (colours_.size() == kCapacity) return -1;
        keys_[slot] = colour;
        index_[slot] = static_cast<std::int16_t>(colours_.size());
        colours_.push_back(colour);
        return index_[slot];
      }
      if (keys_[slot] == colour) return index_[slot];
    }
  }

  // The index of a colour the table holds (the caller knows it does).
  int find(std::uint32_t colour) const {
    std::uint32_t slot = hash(colour);
    while (keys_[slot] != colour || index_[slot] < 0) slot = (slot + 1) & kMask;
    return index_[slot];
  }

  // Packed as load_rgba packs them, in index order.
  const std::vector<std::uint32_t>& colours() const { return colours_; }

 private:
  static constexpr std::uint32_t kBits = 10;
  static constexpr std::uint32_t kMask = (1u << kBits) - 1;
  static std::uint32_t hash(std::uint32_t colour) { return (colour * 0x9E3779B1u) >> (32 - kBits); }

  std::array<std::uint32_t, 1u << kBits> keys_{};
  std::array<std::int16_t, 1u << kBits> index_ = [] {
    std::array<std::int16_t, 1u << kBits> empty{};
    empty.fill(-1);
    return empty;
  }();
  std::vector<std::uint32_t> colours_;
};

}  // namespace toond::image
