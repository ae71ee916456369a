#include "render/cull/facing_runs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace toond::render {
namespace {

// One face's unit normal and height over its longest side (0 and a zero
// normal where it has no area).
struct FaceShape {
  glm::dvec3 normal{0.0};
  double height = 0;
};

FaceShape shape_of(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 cross = glm::cross(b - a, c - a);
  const double twice_area = glm::length(cross);
  const double longest = std::sqrt(std::max({glm::dot(b - a, b - a), glm::dot(c - a, c - a), glm::dot(c - b, c - b)}));
  if (twice_area <= 0.0 || longest <= 0.0) return {};
  return {cross / twice_area, twice_area / longest};
}

}  // namespace

FacingRuns::FacingRuns(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                       std::span<const scene::Submesh> submeshes) {
  const auto at = [&](std::uint32_t e) { return glm::dvec3(positions[indices[e]]); };
  for (const scene::Submesh& sub : submeshes) {
    first_run_.push_back(runs_.size());
    const std::uint32_t end = sub.first_index + sub.index_count;
    for (std::uint32_t first = sub.first_index; first + 2 < end;) {
      const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(kRunTriangles * 3, (end - first) / 3 * 3));
      Run run;
      run.range = {first, count};
      // The ball: round the middle of the corners' box.
      glm::dvec3 low = at(first), high = low;
      for (std::uint32_t e = first; e < first + count; ++e) {
        low = glm::min(low, at(e));
        high = glm::max(high, at(e));
      }
      run.middle = 0.5 * (low + high);
      double radius2 = 0.0;
      for (std::uint32_t e = first; e < first + count; ++e) {
        const glm::dvec3 d = at(e) - run.middle;
        radius2 = std::max(radius2, glm::dot(d, d));
      }
      run.radius = std::sqrt(radius2);
      std::array<glm::dvec3, kRunTriangles> normals;
      glm::dvec3 sum{0.0};
      run.thinnest = std::numeric_limits<double>::infinity();
      for (std::uint32_t t = 0; t < count / 3; ++t) {
        const std::uint32_t e = first + 3 * t;
        const FaceShape face = shape_of(at(e), at(e + 1), at(e + 2));
        normals[t] = face.normal;
        sum += face.normal;
        run.thinnest = std::min(run.thinnest, face.height);
      }
      // The cone: round the normals' mean, as wide as the widest apart.
      const double mean_length = glm::length(sum);
      if (run.thinnest > 0.0 && mean_length > 0.0) {
        run.axis = sum / mean_length;
        run.cos_half_angle = 1.0;
        for (std::uint32_t t = 0; t < count / 3; ++t) {
          run.cos_half_angle = std::min(run.cos_half_angle, glm::dot(normals[t], run.axis));
        }
        run.sin_half_angle = std::sqrt(std::max(0.0, 1.0 - run.cos_half_angle * run.cos_half_angle));
      }
      runs_.push_back(run);
      first += count;
    }
  }
  first_run_.push_back(runs_.size());
}

// With β the angle between the cone's axis and the way from the eye to the
// ball's middle (at distance d) and α the cone's half angle, every normal
// n lies within α + β of that way, so for a point p of a face (within r of
// the middle) n·(eye − p) ≤ −d cos(α + β) + r, while |eye − p| ≤ d + r:
// the face turns away by a cosine of at least t where
// d cos(α + β) − r ≥ t (d + r). Orthographic: n·(toward viewer) ≤
// −cos(α + β), β measured from the rays' way.
bool FacingRuns::surely_turns_away(const Run& run, const MeshViewer& viewer) const {
  if (run.cos_half_angle <= 0.0) return false;
  double cos_beta = 0;
  double distance = 0;
  if (viewer.orthographic) {
    cos_beta = glm::dot(run.axis, viewer.forward);
  } else {
    const glm::dvec3 away = run.middle - viewer.eye;
    distance = glm::length(away);
    if (distance <= run.radius) return false;
    cos_beta = glm::dot(run.axis, away) / distance;
  }
  if (cos_beta <= 0.0) return false;
  const double sin_beta = std::sqrt(std::max(0.0, 1.0 - cos_beta * cos_beta));
  const double cos_sum = run.cos_half_angle * cos_beta - run.sin_half_angle * sin_beta;
  // The turn that outweighs moving a face's corners by the slack: a face
  // of height h over its longest side L, turned by a cosine t, shows at
  // least h L t / 2 square pixels (pixels as large as at the run's
  // farthest), while moving its corners changes that by at most the slack
  // times its sides, under 3 L pixels (as small as at the run's nearest).
  double pixel = viewer.pixel;
  double far_over_near = 1.0;
  if (!viewer.orthographic) {
    pixel *= distance + run.radius;
    far_over_near = (distance + run.radius) / (distance - run.radius);
  }
  const double turn = kMinimumTurn + 6.0 * kSlackPx * pixel * far_over_near / run.thinnest;
  if (viewer.orthographic) return cos_sum >= turn;
  return distance * cos_sum - run.radius >= turn * (distance + run.radius);
}

void FacingRuns::ranges_facing(std::size_t k, const MeshViewer& viewer, std::vector<IndexRange>& out) const {
  out.clear();
  for (std::size_t r = first_run_[k]; r < first_run_[k + 1]; ++r) {
    const Run& run = runs_[r];
    if (surely_turns_away(run, viewer)) continue;
    if (!out.empty() && out.back().first_index + out.back().index_count == run.range.first_index) {
      out.back().index_count += run.range.index_count;
    } else {
      out.push_back(run.range);
    }
  }
}

std::optional<MeshViewer> viewer_in_mesh(const glm::dmat4& model, const Viewer& frame_viewer,
                                         double world_per_px_at_w1) {
  const glm::dmat3 linear(model);
  const double scale = glm::length(linear[0]);
  if (!(scale > 0.0) || !std::isfinite(scale)) return std::nullopt;
  // A similarity's columns are orthogonal and equally long.
  constexpr double kTolerance = 1e-9;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(glm::length(linear[a]) - scale) > kTolerance * scale) return std::nullopt;
    for (int b = a + 1; b < 3; ++b) {
      if (std::abs(glm::dot(linear[a], linear[b])) > kTolerance * scale * scale) return std::nullopt;
    }
  }
  const glm::dmat4 to_mesh = glm::inverse(model);
  MeshViewer viewer;
  viewer.orthographic = frame_viewer.orthographic;
  viewer.eye = glm::dvec3(to_mesh * glm::dvec4(frame_viewer.eye, 1.0));
  viewer.forward = glm::normalize(glm::dmat3(to_mesh) * frame_viewer.forward);
  // Perspective: a pixel at frame distance s·d is world_per_px_at_w1 · w ≤
  // world_per_px_at_w1 · s·d frame units, that is world_per_px_at_w1 · d
  // mesh units. Orthographic: world_per_px_at_w1 frame units everywhere.
  viewer.pixel = viewer.orthographic ? world_per_px_at_w1 / scale : world_per_px_at_w1;
  return viewer;
}

}  // namespace toond::render
