#include "render/cull/cover_layers.h"

#include <algorithm>
#include <cmath>

namespace toond::render {
namespace {

// A cell lowered this often is open, however many more edges meet it (the
// count saturates here rather than wrap).
constexpr int kSaturated = 255;

double l1(const glm::dvec2& v) { return std::abs(v.x) + std::abs(v.y); }

double cross(const glm::dvec2& u, const glm::dvec2& v) { return u.x * v.y - u.y * v.x; }

// The index of the cell of size `cell` holding v, counted from 0 at 0.
int cell_index(double v, double per_px) { return static_cast<int>(std::floor(v * per_px)); }

}  // namespace

void CoverLayers::reset(const Grid& grid, bool drawn_counter_clockwise, double slack_px) {
  cell_ = grid.cell;
  per_px_ = 1.0 / grid.cell;
  // The cells of the viewport the box overlaps, at the viewport's own
  // multiples of the cell size.
  const int last_column = std::max(0, static_cast<int>(std::ceil(grid.width * per_px_)) - 1);
  const int last_row = std::max(0, static_cast<int>(std::ceil(grid.height * per_px_)) - 1);
  const int x0 = std::clamp(cell_index(std::max(grid.lo.x, 0.0), per_px_), 0, last_column);
  const int y0 = std::clamp(cell_index(std::max(grid.lo.y, 0.0), per_px_), 0, last_row);
  const int x1 = std::clamp(cell_index(std::min(grid.hi.x, static_cast<double>(grid.width)), per_px_), x0, last_column);
  const int y1 = std::clamp(cell_index(std::min(grid.hi.y, static_cast<double>(grid.height)), per_px_), y0, last_row);
  first_column_ = x0;
  first_row_ = y0;
  columns_ = x1 - x0 + 1;
  rows_ = y1 - y0 + 1;
  face_side_ = drawn_counter_clockwise ? 1.0 : -1.0;
  slack_ = slack_px;
  crossings_.assign(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(columns_ + 1), 0);
  lowered_.assign(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(columns_), 0);
  last_lowered_.clear();
  any_edge_ = false;
}

void CoverLayers::add_outline_edge(const glm::dvec2& a, const glm::dvec2& b) {
  if (a == b) return;  // no length: nothing crosses it, snapped or not
  const bool follows = any_edge_ && a == last_end_;
  const glm::dvec2 origin = first_corner();
  add_row_crossings(a - origin, b - origin);
  lower_cells_met(a - origin, b - origin, follows);
  any_edge_ = true;
  last_end_ = b;
}

// Read along a row: an edge walked downward has a counter-clockwise face
// on its +x side, so the cells past it gain one; walked upward, they lose
// one. (In the grid's coordinates: its first cell's corner at 0.)
void CoverLayers::add_row_crossings(const glm::dvec2& a, const glm::dvec2& b) {
  const double low = std::min(a.y, b.y), high = std::max(a.y, b.y);
  // Rows whose centre y = (j + 0.5) cell lies in [low, high).
  const int first = static_cast<int>(std::ceil(std::clamp(low * per_px_ - 0.5, 0.0, static_cast<double>(rows_))));
  const int last = static_cast<int>(std::floor(std::clamp(high * per_px_ - 0.5, -1.0, rows_ - 1.0)));
  const std::int32_t step = b.y < a.y ? 1 : -1;
  const double dx_per_y = (b.x - a.x) / (b.y - a.y);
  for (int j = first; j <= last; ++j) {
    const double y = (j + 0.5) * cell_;
    if ((a.y <= y) == (b.y <= y)) continue;  // the same half-open rule for both edges at a shared vertex
    const double x = a.x + (y - a.y) * dx_per_y;
    // The first cell whose centre lies past x.
    const double past = std::clamp(x * per_px_ - 0.5, -1.0, static_cast<double>(columns_));
    const int column = past < 0.0 ? 0 : std::min(columns_, static_cast<int>(past) + 1);
    crossings_[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns_ + 1) +
               static_cast<std::size_t>(column)] += step;
  }
}

// Every cell whose square, grown by the slack, the edge meets: its count
// may fall across the edge where the centre lies on the face's side, or
// too near the edge's line to say after the ends move. That also covers a
// centre the edge passes too near for its count to be read surely: the
// count read there is off by at most this edge's one, toward the face's
// side, which the lowering takes back.
void CoverLayers::lower_cells_met(const glm::dvec2& a, const glm::dvec2& b, bool follows) {
  const double reach = 2.0 * slack_;  // the slack, and the rounding here well inside it again
  const glm::dvec2 along = b - a;
  const double low = std::min(a.y, b.y) - reach, high = std::max(a.y, b.y) + reach;
  const int first = std::max(0, row(low)), last = std::min(rows_ - 1, row(high));
  for (int j = first; j <= last; ++j) {
    // The part of the edge within the row's band grown by the reach.
    const double band_low = std::max(low, j * cell_ - reach), band_high = std::min(high, (j + 1) * cell_ + reach);
    double x_low = std::min(a.x, b.x), x_high = std::max(a.x, b.x);
    if (along.y != 0.0) {
      const double t0 = std::clamp((band_low - a.y) / along.y, 0.0, 1.0);
      const double t1 = std::clamp((band_high - a.y) / along.y, 0.0, 1.0);
      x_low = a.x + along.x * std::min(t0, t1);
      x_high = a.x + along.x * std::max(t0, t1);
      if (x_low > x_high) std::swap(x_low, x_high);
    }
    const int begin = std::max(0, column(x_low - reach)), end = std::min(columns_ - 1, column(x_high + reach));
    for (int i = begin; i <= end; ++i) {
      const glm::dvec2 to_centre = glm::dvec2((i + 0.5) * cell_, (j + 0.5) * cell_) - a;
      // With each end moved by up to `reach`, the cross product moves by
      // at most this much.
      const double doubt = reach * (l1(along) + 2.0 * l1(to_centre)) + 2.0 * reach * reach;
      if (face_side_ * cross(along, to_centre) <= -doubt) continue;
      const std::size_t cell = at(i, j);
      if (follows && std::find(last_lowered_.begin(), last_lowered_.end(), cell) != last_lowered_.end()) {
        continue;  // counted once, with the edge before
      }
      lowered_[cell] = static_cast<std::uint8_t>(std::min<int>(lowered_[cell] + 1, kSaturated));
      lowering_.push_back(cell);
    }
  }
  last_lowered_.swap(lowering_);
  lowering_.clear();
}

void CoverLayers::finish() {
  open_sums_.assign(static_cast<std::size_t>(columns_ + 1) * static_cast<std::size_t>(rows_ + 1), 0);
  const int side = face_side_ > 0.0 ? 1 : -1;
  for (int j = 0; j < rows_; ++j) {
    const std::int32_t* crossings = &crossings_[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns_ + 1)];
    const std::uint8_t* lowered = &lowered_[at(0, j)];
    const std::int32_t* above = &open_sums_[sum_at(1, j)];
    std::int32_t* sums = &open_sums_[sum_at(1, j + 1)];
    int count = 0, open_along = 0;
    for (int i = 0; i < columns_; ++i) {
      count += crossings[i];
      open_along += lowered[i] == kSaturated || side * count - lowered[i] < 1;
      sums[i] = above[i] + open_along;
    }
  }
}

bool CoverLayers::covers(const glm::dvec2& lo, const glm::dvec2& hi) const {
  const glm::dvec2 origin = first_corner();
  return covers(column(lo.x - origin.x) + first_column_, column(hi.x - origin.x) + 1 + first_column_,
                row(lo.y - origin.y) + first_row_, row(hi.y - origin.y) + 1 + first_row_);
}

bool CoverLayers::covers(int x0, int x1, int y0, int y1) const {
  x0 -= first_column_;
  x1 -= first_column_;
  y0 -= first_row_;
  y1 -= first_row_;
  if (x0 < 0 || y0 < 0 || x1 > columns_ || y1 > rows_) return false;  // off the grid: open
  return open_sums_[sum_at(x1, y1)] - open_sums_[sum_at(x0, y1)] - open_sums_[sum_at(x1, y0)] +
             open_sums_[sum_at(x0, y0)] ==
         0;
}

// Clamped to one cell past either end first, so truncating is flooring.
int CoverLayers::column(double x) const {
  return static_cast<int>(std::clamp(x * per_px_, -1.0, static_cast<double>(columns_)) + 1.0) - 1;
}
int CoverLayers::row(double y) const {
  return static_cast<int>(std::clamp(y * per_px_, -1.0, static_cast<double>(rows_)) + 1.0) - 1;
}

}  // namespace toond::render
