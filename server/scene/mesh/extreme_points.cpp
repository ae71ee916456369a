#include "scene/mesh/extreme_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace toond::scene {
namespace {

// Points of a golden-angle spiral: nearly even spacing for any count.
std::array<glm::dvec3, kExtremeDirections> sphere_spiral_directions() {
  std::array<glm::dvec3, kExtremeDirections> dirs{};
  const double golden_angle = std::acos(-1.0) * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kExtremeDirections; ++i) {
    const double y = 1.0 - (i + 0.5) * 2.0 / kExtremeDirections;
    const double r = std::sqrt(1.0 - y * y);
    const double a = golden_angle * i;
    dirs[static_cast<std::size_t>(i)] = {r * std::cos(a), y, r * std::sin(a)};
  }
  return dirs;
}

// Consecutive positions in blocks of this many, each bounded by a sphere.
constexpr std::size_t kBlock = 32;

struct Block {
  glm::dvec3 centre{0.0};
  double radius = 0;
  double slack = 0;  // added to a bound so that rounding never makes it too small
};

std::vector<Block> blocks_of(std::span<const glm::vec3> positions) {
  std::vector<Block> blocks;
  blocks.reserve((positions.size() + kBlock - 1) / kBlock);
  for (std::size_t first = 0; first < positions.size(); first += kBlock) {
    const std::span<const glm::vec3> part = positions.subspan(first, std::min(kBlock, positions.size() - first));
    glm::dvec3 low(part.front()), high(part.front());
    for (const glm::vec3& p : part) {
      low = glm::min(low, glm::dvec3(p));
      high = glm::max(high, glm::dvec3(p));
    }
    Block block;
    block.centre = 0.5 * (low + high);
    for (const glm::vec3& p : part) block.radius = std::max(block.radius, glm::length(glm::dvec3(p) - block.centre));
    block.slack = 1e-9 * (glm::length(block.centre) + block.radius);
    blocks.push_back(block);
  }
  return blocks;
}

// The index of the first position farthest along `dir` (as a scan of every
// position keeping the first of equals would find it), scanning only the
// blocks whose sphere reaches as far as the best point found so far. The
// block that reaches farthest is scanned first, so nearly every other block
// is skipped where positions run along the surface, as a file's do.
std::size_t farthest_along(const glm::dvec3& dir, std::span<const glm::vec3> positions,
                           const std::vector<Block>& blocks) {
  const auto reach_of = [&](const Block& block) { return glm::dot(block.centre, dir) + block.radius + block.slack; };
  double best = -std::numeric_limits<double>::infinity();
  std::size_t best_index = 0;
  const auto scan = [&](std::size_t b) {
    const std::size_t first = b * kBlock, last = std::min(first + kBlock, positions.size());
    for (std::size_t v = first; v < last; ++v) {
      const double reach = glm::dot(glm::dvec3(positions[v]), dir);
      if (reach > best || (reach == best && v < best_index)) {
        best = reach;
        best_index = v;
      }
    }
  };
  std::size_t farthest_block = 0;
  for (std::size_t b = 1; b < blocks.size(); ++b) {
    if (reach_of(blocks[b]) > reach_of(blocks[farthest_block])) farthest_block = b;
  }
  scan(farthest_block);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (b != farthest_block && !(reach_of(blocks[b]) < best)) scan(b);
  }
  return best_index;
}

}  // namespace

std::vector<glm::vec3> extreme_points(std::span<const glm::vec3> positions) {
  if (positions.empty()) return {};
  static const std::array<glm::dvec3, kExtremeDirections> dirs = sphere_spiral_directions();
  const std::vector<Block> blocks = blocks_of(positions);
  std::array<std::size_t, kExtremeDirections> best_index{};
  for (std::size_t d = 0; d < dirs.size(); ++d) best_index[d] = farthest_along(dirs[d], positions, blocks);
  std::sort(best_index.begin(), best_index.end());
  std::vector<glm::vec3> points;
  for (std::size_t i = 0; i < best_index.size(); ++i) {
    if (i == 0 || best_index[i] != best_index[i - 1]) points.push_back(positions[best_index[i]]);
  }
  return points;
}

std::vector<glm::vec3> extreme_points(std::span<const glm::vec3> positions,
                                      std::span<const std::uint32_t> position_group) {
  // Groups are numbered in order of first appearance, so a vertex is the
  // first at its point when its group is the next number.
  std::vector<glm::vec3> firsts;
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    if (position_group[v] == next) {
      firsts.push_back(positions[v]);
      ++next;
    }
  }
  return extreme_points(firsts);
}

}  // namespace toond::scene
