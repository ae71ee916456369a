#pragma once
// Disjoint sets over 0..n-1 (union-find with path halving): which of n
// things hang together once pairs are joined. Near-constant time a call.
#include <cstdint>
#include <numeric>
#include <vector>

namespace toond::scene {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }

  // The representative of v's set.
  std::uint32_t root(std::uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[a] = b;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace toond::scene
