#include "render/vector/contour_filter.h"

#include <cmath>

namespace toond::render::vector {
namespace {

// Judges points of one segment: whether the line shows there under the rule.
class ContourJudge {
 public:
  ContourJudge(const OccluderGrid& grid, const ScreenMap& screen, const LineChoice& choice, double reach_px)
      : grid_(grid), screen_(screen), choice_(choice), reach_(reach_px) {}

  // The segment's screen direction and its far side, away from its surface.
  void start(const Segment& s) {
    const glm::dvec2 p = screen_.to_pixels(s.a), q = screen_.to_pixels(s.b);
    const glm::dvec2 along = q - p;
    const double length = glm::length(along);
    const glm::dvec2 across = length > 0 ? glm::dvec2(-along.y, along.x) / length : glm::dvec2(0.0);
    const glm::dvec2 side = screen_.to_pixels(s.surface_side) - p;
    away_ = glm::dot(across, side) > 0 ? -across : across;
  }

  bool drawn_at(const glm::dvec3& point) {
    const double beyond = grid_.first_depth(screen_.to_pixels(point) + reach_ * away_, screen_, nearby_, scratch_);
    if (beyond < 0) return true;  // the outline: nothing there
    return choice_.contours == ContourRule::DepthJump && beyond - (-point.z) > choice_.depth_jump;
  }

 private:
  const OccluderGrid& grid_;
  const ScreenMap& screen_;
  const LineChoice& choice_;
  double reach_;
  glm::dvec2 away_{0.0};
  std::vector<std::uint32_t> nearby_;
  GatherScratch scratch_;
};

// The piece cut into runs of steps, about a pixel each, that the judge keeps.
void add_kept_runs(const Piece& piece, const Segment& s, const ScreenMap& screen, ContourJudge& judge,
                   std::vector<Piece>& out) {
  const glm::dvec3 d = s.b - s.a;
  const double length_px = glm::length(screen.to_pixels(s.a + piece.t1 * d) - screen.to_pixels(s.a + piece.t0 * d));
  const int steps = std::max(1, static_cast<int>(std::ceil(length_px)));
  const double dt = (piece.t1 - piece.t0) / steps;
  judge.start(s);
  int run_start = -1;
  for (int i = 0; i <= steps; ++i) {
    const bool kept = i < steps && judge.drawn_at(s.a + (piece.t0 + (i + 0.5) * dt) * d);
    if (kept && run_start < 0) run_start = i;
    if (!kept && run_start >= 0) {
      // The piece's own ends where a run reaches them, so they still join.
      const double t0 = run_start == 0 ? piece.t0 : piece.t0 + run_start * dt;
      const double t1 = i == steps ? piece.t1 : piece.t0 + i * dt;
      out.push_back({piece.segment, t0, t1, false});
      run_start = -1;
    }
  }
}

}  // namespace

std::vector<Piece> keep_drawn_contours(const std::vector<Piece>& pieces, const std::vector<Segment>& segments,
                                       const OccluderGrid& grid, const ScreenMap& screen, const LineChoice& choice,
                                       double reach_px) {
  if (choice.contours == ContourRule::All) return pieces;
  ContourJudge judge(grid, screen, choice, reach_px);
  std::vector<Piece> out;
  out.reserve(pieces.size());
  for (const Piece& piece : pieces) {
    const Segment& s = segments[piece.segment];
    const bool contour = s.kind == LineKind::Silhouette || s.kind == LineKind::Boundary;
    if (piece.hidden || !contour) {
      out.push_back(piece);
    } else {
      add_kept_runs(piece, s, screen, judge, out);
    }
  }
  return out;
}

}  // namespace toond::render::vector
