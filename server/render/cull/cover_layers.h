#pragma once
// How many layers of drawn faces surely lie over each cell of a grid over
// the viewport: the test that lets the hull cull (hull_cull.h) leave out
// faces near a fold inside the model, where the cover's edge crosses the
// face's box but more faces lie behind it.
//
// Count every face of a chain (the faces drawn, and those too thin to say
// which way they turn) once, as it is walked. Inside a face walked the
// drawn way the count gains one, inside one walked the other way it loses
// one, so wherever it is at least one some face drawn the drawn way lies
// there: the point is covered. The count is the winding number of the
// chain's outline (the edges no other face of the chain walks back), so it
// changes only across those edges, by one each, and a cell's centre, read
// off the outline's crossings along its row, bounds it over the whole
// cell: along a straight way from the centre it falls by one at each
// outline edge crossed from its face's side, so by at most the number of
// edges meeting the cell with the centre on their faces' side. Two edges
// one after the other along the outline (the first's end the second's
// start) count once: a straight way that crosses both crosses them in
// opposite senses, so together they lower the count by one at most, and a
// run of such edges counts half its length, rounded up. Snapping the
// vertices to the rasterizer's grid moves an edge by at most the slack
// (and keeps a shared end shared): the cells are grown by it, and a centre
// counts as on an edge's other side only beyond what the move could turn.
//
// Pure arithmetic, no GL.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace toond::render {

class CoverLayers {
 public:
  // Nothing counted, over the cells of `cell` px of a viewport of this
  // size that overlap the box [lo, hi] (where the faces lie: every other
  // cell is open); `drawn_counter_clockwise`: the drawn faces' winding in
  // window coordinates (y up); `slack_px`: how far the rasterizer may move
  // a vertex from where the caller puts it.
  struct Grid {
    int width = 0, height = 0;
    double cell = 1.0;
    glm::dvec2 lo{0.0}, hi{0.0};
  };
  void reset(const Grid& grid, bool drawn_counter_clockwise, double slack_px);

  // One edge of the chain's outline, walked as its face walks it. Edges
  // given along the outline, each starting where the one before ended,
  // lower the cells they share by less (see above).
  void add_outline_edge(const glm::dvec2& a, const glm::dvec2& b);

  // After the last edge: the counts, and which cells are surely covered.
  void finish();

  // Whether every cell the box [lo, hi] overlaps is surely covered at every
  // point.
  bool covers(const glm::dvec2& lo, const glm::dvec2& hi) const;
  // The same for the viewport's cells (of the size given to reset, counted
  // from 0 at 0) in columns [x0, x1) and rows [y0, y1).
  bool covers(int x0, int x1, int y0, int y1) const;

 private:
  void add_row_crossings(const glm::dvec2& a, const glm::dvec2& b);
  void lower_cells_met(const glm::dvec2& a, const glm::dvec2& b, bool follows);
  // The grid's column and row holding x and y, clamped to one past its
  // ends (-1 or columns_/rows_).
  int column(double x) const;
  int row(double y) const;
  // The first cell's corner, in pixels.
  glm::dvec2 first_corner() const { return glm::dvec2(first_column_, first_row_) * cell_; }
  std::size_t at(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
  }
  std::size_t sum_at(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_ + 1) + static_cast<std::size_t>(column);
  }

  double cell_ = 1.0, per_px_ = 1.0;
  int first_column_ = 0, first_row_ = 0;  // the first cell's, among the viewport's
  int columns_ = 0, rows_ = 0;
  double face_side_ = 1.0;  // +1 where drawn faces lie left of their edges
  double slack_ = 0.0;
  // Per row, columns_ + 1 entries: the change in the count from the cell
  // before to this one (the last, past the grid, takes crossings there).
  std::vector<std::int32_t> crossings_;
  // Per cell: outline edges that may lower the count from its centre.
  std::vector<std::uint8_t> lowered_;
  // The cells the last edge lowered, and those of the edge being added:
  // an edge that follows the last one is counted with it in the cells both
  // lower (once per pair: a cell the last edge left paired counts again).
  std::vector<std::size_t> last_lowered_, lowering_;
  glm::dvec2 last_end_{0.0};  // where the last edge added ended
  bool any_edge_ = false;
  // Summed over the cells above and left: cells not surely covered.
  std::vector<std::int32_t> open_sums_;
};

}  // namespace toond::render
