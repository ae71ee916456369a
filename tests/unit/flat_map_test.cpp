// The import's insert-only hash map: the first value of a key stays, every
// key is found again after the index grows, and a weak hash (the identity
// of keys that differ only in their high bits) still spreads.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>

#include "scene/mesh/flat_map.h"

namespace toond::scene {
namespace {

TEST(FlatMap, KeepsTheFirstValueOfEachKeyAndFindsEveryKeyAfterGrowing) {
  FlatMap<std::uint64_t, std::uint32_t, std::hash<std::uint64_t>> map;
  constexpr std::uint32_t kKeys = 100000;
  for (std::uint32_t k = 0; k < kKeys; ++k) {
    const auto [value, added] = map.try_emplace(std::uint64_t{k} << 32, k);
    ASSERT_TRUE(added);
    ASSERT_EQ(value, k);
  }
  EXPECT_EQ(map.size(), kKeys);
  for (std::uint32_t k = 0; k < kKeys; k += 7) {
    auto [value, added] = map.try_emplace(std::uint64_t{k} << 32, 0u);
    EXPECT_FALSE(added);
    EXPECT_EQ(value, k);
    value = k + 1;  // a value is changed in place
  }
  EXPECT_EQ(map.size(), kKeys);
  for (std::uint32_t k = 0; k < kKeys; ++k) {
    const std::uint32_t* value = map.find(std::uint64_t{k} << 32);
    ASSERT_NE(value, nullptr) << k;
    EXPECT_EQ(*value, k % 7 == 0 ? k + 1 : k);
  }
  EXPECT_EQ(map.find(std::uint64_t{kKeys} << 32), nullptr);
  EXPECT_EQ(map.find(1), nullptr);
}

TEST(FlatMap, AnEmptyMapFindsNothing) {
  const FlatMap<std::uint32_t, int, std::hash<std::uint32_t>> map;
  EXPECT_EQ(map.size(), 0u);
  EXPECT_EQ(map.find(0), nullptr);
}

}  // namespace
}  // namespace toond::scene
