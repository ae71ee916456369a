#include "scene/mesh/position_weld.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace toond::scene {
namespace {

// A cell's coordinates, each shifted by one (so a neighbour at -1 is 0)
// and packed into 21 bits: with cells of 2e-6 of the box's diagonal there
// are at most 5e5 along an axis. 0 marks an empty slot.
using Cell = std::uint64_t;

Cell pack(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::uint64_t kMask = (1u << 21) - 1;
  return ((static_cast<std::uint64_t>(x + 1) & kMask) << 42 | (static_cast<std::uint64_t>(y + 1) & kMask) << 21 |
          (static_cast<std::uint64_t>(z + 1) & kMask)) +
         1;
}

// Cell → the last position kept in it. Open addressing in one flat array
// sized once for every position: no allocation per cell, so the weld's
// time follows the number of positions.
class CellTable {
 public:
  static constexpr std::uint32_t kNone = ~0u;
  explicit CellTable(std::size_t capacity) {
    std::size_t size = 16;
    while (size < 2 * capacity) size *= 2;
    slots_.assign(size, Slot{});
  }
  // The value for `cell`, created (kNone) if missing.
  std::uint32_t& at(Cell cell) {
    Slot& slot = slots_[find(cell)];
    slot.cell = cell;
    return slot.value;
  }
  std::uint32_t get(Cell cell) const { return slots_[find(cell)].value; }

 private:
  struct Slot {
    Cell cell = 0;
    std::uint32_t value = kNone;
  };
  std::size_t find(Cell cell) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = static_cast<std::size_t>((cell * 0x9E3779B97F4A7C15ull) >> 20) & mask;
    while (slots_[i].cell != 0 && slots_[i].cell != cell) i = (i + 1) & mask;
    return i;
  }
  std::vector<Slot> slots_;
};

struct Box {
  glm::dvec3 min{0.0}, max{0.0};
};

Box box_of(std::span<const glm::vec3> positions) {
  Box box{glm::dvec3(positions.front()), glm::dvec3(positions.front())};
  for (const glm::vec3& p : positions) {
    box.min = glm::min(box.min, glm::dvec3(p));
    box.max = glm::max(box.max, glm::dvec3(p));
  }
  return box;
}

}  // namespace

WeldReport weld_positions(std::span<glm::vec3> positions) {
  WeldReport report;
  if (positions.empty()) return report;
  const Box box = box_of(positions);
  report.tolerance = glm::length(box.max - box.min) * kWeldRelativeTolerance;
  if (!(report.tolerance > 0.0) || !std::isfinite(report.tolerance)) return report;

  // Cells twice the tolerance wide: every kept point within the tolerance
  // of a point lies in its cell or in the neighbours on the sides of the
  // cell's middle the point is on, 8 cells in all.
  const double cell_size = 2.0 * report.tolerance;
  // Kept positions by cell, as chains through `next_kept` (no allocation
  // per cell): the head of each cell's chain, and for each kept position
  // the one kept before it in the same cell.
  constexpr std::uint32_t kNone = CellTable::kNone;
  CellTable last_kept(positions.size());
  std::vector<std::uint32_t> next_kept(positions.size(), kNone);
  const double tolerance_sq = report.tolerance * report.tolerance;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const glm::dvec3 p(positions[v]);
    const glm::dvec3 scaled = (p - box.min) / cell_size;
    const glm::dvec3 floor = glm::floor(scaled);
    const std::int64_t hx = static_cast<std::int64_t>(floor.x), hy = static_cast<std::int64_t>(floor.y),
                       hz = static_cast<std::int64_t>(floor.z);
    // Toward the nearer neighbour on each axis.
    const glm::dvec3 side =
        glm::mix(glm::dvec3(-1.0), glm::dvec3(1.0), glm::greaterThanEqual(scaled - floor, glm::dvec3(0.5)));
    const glm::vec3* nearest = nullptr;
    double nearest_sq = tolerance_sq;
    for (const std::int64_t dx : {std::int64_t{0}, static_cast<std::int64_t>(side.x)}) {
      for (const std::int64_t dy : {std::int64_t{0}, static_cast<std::int64_t>(side.y)}) {
        for (const std::int64_t dz : {std::int64_t{0}, static_cast<std::int64_t>(side.z)}) {
          for (std::uint32_t k = last_kept.get(pack(hx + dx, hy + dy, hz + dz)); k != kNone; k = next_kept[k]) {
            const glm::dvec3 d = glm::dvec3(positions[k]) - p;
            const double dist_sq = glm::dot(d, d);
            if (dist_sq <= nearest_sq) {
              nearest_sq = dist_sq;
              nearest = &positions[k];
            }
          }
        }
      }
    }
    if (nearest) {
      if (*nearest != positions[v]) ++report.moved;
      positions[v] = *nearest;
    } else {
      std::uint32_t& head = last_kept.at(pack(hx, hy, hz));
      next_kept[v] = head;
      head = static_cast<std::uint32_t>(v);
    }
  }
  return report;
}

}  // namespace toond::scene
