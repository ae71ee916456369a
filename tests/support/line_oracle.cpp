#include "support/line_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toond::test {

glm::dvec2 MetaCamera::project(const glm::dvec3& p) const {
  const glm::dvec4 clip = projection * view * glm::dvec4(p, 1.0);
  return {(clip.x / clip.w * 0.5 + 0.5) * width, (0.5 - clip.y / clip.w * 0.5) * height};
}

std::pair<glm::dvec3, glm::dvec3> MetaCamera::ray_through(glm::dvec2 px) const {
  const glm::dmat4 back = glm::inverse(projection * view);
  const auto at = [&](double z) {
    const glm::dvec4 p = back * glm::dvec4(px.x / width * 2 - 1, 1 - px.y / height * 2, z, 1);
    return glm::dvec3(p) / p.w;
  };
  const glm::dvec3 near = at(-1), far = at(1);
  return {near, glm::normalize(far - near)};
}

glm::dvec3 MetaCamera::ray_origin(const glm::dvec3& p, double far) const {
  return orthographic ? p - forward * far : eye;
}

MetaCamera camera_from_metadata(const nlohmann::json& json) {
  MetaCamera camera;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      camera.view[c][r] = json["view"][4 * c + r].get<double>();
      camera.projection[c][r] = json["projection"][4 * c + r].get<double>();
    }
  }
  camera.width = json["width"];
  camera.height = json["height"];
  // A perspective projection puts -z into w; an orthographic one keeps w = 1.
  camera.orthographic = camera.projection[3][3] == 1.0;
  const glm::dmat4 to_world = glm::inverse(camera.view);
  camera.eye = glm::dvec3(to_world[3]);
  camera.forward = -glm::normalize(glm::dvec3(to_world[2]));
  return camera;
}

std::vector<std::pair<glm::dvec3, glm::dvec3>> box_edges(const Box& box) {
  const auto corner = [&](int i) {
    return glm::dvec3(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z);
  };
  std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
  for (int i = 0; i < 8; ++i) {
    for (int bit : {1, 2, 4}) {
      if (!(i & bit)) edges.emplace_back(corner(i), corner(i | bit));
    }
  }
  return edges;
}

bool ray_meets_boxes(const MetaCamera& camera, const std::vector<Box>& boxes, glm::dvec2 px) {
  const auto [origin, dir] = camera.ray_through(px);
  for (const Box& box : boxes) {
    double enter = 0, leave = std::numeric_limits<double>::max();
    for (int k = 0; k < 3; ++k) {
      if (std::abs(dir[k]) < 1e-15) {
        if (origin[k] < box.lo[k] || origin[k] > box.hi[k]) leave = -1;
        continue;
      }
      const double t0 = (box.lo[k] - origin[k]) / dir[k], t1 = (box.hi[k] - origin[k]) / dir[k];
      enter = std::max(enter, std::min(t0, t1));
      leave = std::min(leave, std::max(t0, t1));
    }
    if (enter <= leave) return true;
  }
  return false;
}

bool seen_among_boxes(const MetaCamera& camera, const std::vector<Box>& boxes, const glm::dvec3& p) {
  const glm::dvec3 origin = camera.ray_origin(p, 1e3);
  const glm::dvec3 d = p - origin;  // p at t = 1
  for (const Box& box : boxes) {
    // The slabs: where the ray is inside the box on every axis.
    double enter = -std::numeric_limits<double>::max(), leave = std::numeric_limits<double>::max();
    for (int k = 0; k < 3; ++k) {
      if (std::abs(d[k]) < 1e-15) {
        if (origin[k] < box.lo[k] || origin[k] > box.hi[k]) enter = leave = 2;  // misses
        continue;
      }
      const double t0 = (box.lo[k] - origin[k]) / d[k], t1 = (box.hi[k] - origin[k]) / d[k];
      enter = std::max(enter, std::min(t0, t1));
      leave = std::min(leave, std::max(t0, t1));
    }
    // Entered before reaching p, and not only grazed along a face.
    if (enter < leave - 1e-9 && enter > 0 && enter < 1 - 1e-7) return false;
  }
  return true;
}

double Torus::distance(const glm::dvec3& p) const {
  const glm::dvec2 q(std::hypot(p.x, p.z) - major, p.y);
  return glm::length(q) - minor;
}

bool seen_on_torus(const MetaCamera& camera, const Torus& torus, const glm::dvec3& p) {
  const glm::dvec3 origin = camera.ray_origin(p, 10.0);
  const double reach = glm::length(p - origin);
  const glm::dvec3 dir = (p - origin) / reach;
  // Marched, in steps no longer than the distance to the surface (and no
  // shorter than a tiny step, near a grazing point), until the surface is
  // met or p is all but reached.
  const double stop = reach - 2e-3 * torus.major;
  for (double t = 0; t < stop;) {
    const double d = torus.distance(origin + t * dir);
    if (d < 0) return false;
    t += std::max(d, 1e-5 * torus.major);
  }
  return true;
}

bool ray_meets_torus(const MetaCamera& camera, const Torus& torus, glm::dvec2 px) {
  const auto [origin, dir] = camera.ray_through(px);
  const double reach = 20.0 * (torus.major + torus.minor) + glm::length(origin);
  for (double t = 0; t < reach;) {
    const double d = torus.distance(origin + t * dir);
    if (d < 1e-7) return true;
    t += d;
  }
  return false;
}

glm::dvec3 torus_normal(const Torus& torus, const glm::dvec3& p) {
  const glm::dvec3 ring = glm::dvec3(p.x, 0, p.z) * (torus.major / std::hypot(p.x, p.z));
  return glm::normalize(p - ring);
}

namespace {

// The tube angles v at ring angle u where the torus turns edge-on to the eye.
std::vector<double> edge_on_angles(const MetaCamera& camera, const Torus& torus, double u) {
  const double pi = std::acos(-1.0);
  const auto edge_on = [&](double v) {
    const glm::dvec3 n(std::cos(v) * std::cos(u), std::sin(v), std::cos(v) * std::sin(u));
    const glm::dvec3 p = glm::dvec3(torus.major * std::cos(u), 0, torus.major * std::sin(u)) + torus.minor * n;
    return glm::dot(n, camera.orthographic ? camera.forward : p - camera.eye);
  };
  std::vector<double> angles;
  const int steps = 720;
  for (int k = 0; k < steps; ++k) {
    double v0 = 2 * pi * k / steps, v1 = 2 * pi * (k + 1) / steps;
    double f0 = edge_on(v0);
    if ((f0 < 0) == (edge_on(v1) < 0)) continue;
    for (int b = 0; b < 50; ++b) {
      const double vm = 0.5 * (v0 + v1), fm = edge_on(vm);
      if ((fm < 0) == (f0 < 0)) {
        v0 = vm;
        f0 = fm;
      } else {
        v1 = vm;
      }
    }
    angles.push_back(0.5 * (v0 + v1));
  }
  return angles;
}

glm::dvec3 torus_point(const Torus& torus, double u, double v) {
  return glm::dvec3((torus.major + torus.minor * std::cos(v)) * std::cos(u), torus.minor * std::sin(v),
                    (torus.major + torus.minor * std::cos(v)) * std::sin(u));
}

}  // namespace

TorusContourPoints torus_contour(const MetaCamera& camera, const Torus& torus, int around) {
  const double pi = std::acos(-1.0);
  TorusContourPoints out;
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(around));
  for (int i = 0; i < around; ++i) {
    const double u = 2 * pi * i / around;
    rows[i] = edge_on_angles(camera, torus, u);
    for (double v : rows[i]) out.points.push_back(torus_point(torus, u, v));
  }
  // Each branch followed through three rows: the nearest angle in the next
  // row continues it; where its two steps on screen point apart, a cusp.
  const auto nearest = [&](const std::vector<double>& row, double v) {
    double best = v, gap = 1e9;
    for (double w : row) {
      const double d = std::abs(std::remainder(w - v, 2 * pi));
      if (d < gap) {
        gap = d;
        best = w;
      }
    }
    return best;
  };
  for (int i = 0; i < around; ++i) {
    const int j = (i + 1) % around, k = (i + 2) % around;
    const double u0 = 2 * pi * i / around, u1 = 2 * pi * j / around, u2 = 2 * pi * k / around;
    for (double v0 : rows[i]) {
      if (rows[j].empty() || rows[k].empty()) continue;
      const double v1 = nearest(rows[j], v0), v2 = nearest(rows[k], v1);
      const glm::dvec2 a = camera.project(torus_point(torus, u0, v0));
      const glm::dvec2 b = camera.project(torus_point(torus, u1, v1));
      const glm::dvec2 c = camera.project(torus_point(torus, u2, v2));
      if (glm::dot(b - a, c - b) < 0) out.cusps.push_back(torus_point(torus, u1, v1));
    }
  }
  return out;
}

double SampledLine::seen_share() const {
  if (seen.empty()) return 0;
  return static_cast<double>(std::count(seen.begin(), seen.end(), true)) / static_cast<double>(seen.size());
}

SampledLine sample_line(const MetaCamera& camera, const glm::dvec3& a, const glm::dvec3& b,
                        const std::function<bool(const glm::dvec3&)>& seen, int samples) {
  SampledLine line;
  for (int i = 0; i <= samples; ++i) {
    const glm::dvec3 p = glm::mix(a, b, static_cast<double>(i) / samples);
    line.at.push_back(camera.project(p));
    line.seen.push_back(seen(p));
  }
  return line;
}

std::vector<std::pair<glm::dvec2, glm::dvec2>> seen_stretches(const std::vector<SampledLine>& lines) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> out;
  for (const SampledLine& line : lines) {
    for (std::size_t i = 0; i < line.at.size(); ++i) {
      if (!line.seen[i]) continue;
      // A lone seen sample is a stretch of no length, still a place a line may be.
      const bool next = i + 1 < line.at.size() && line.seen[i + 1];
      out.emplace_back(line.at[i], next ? line.at[i + 1] : line.at[i]);
    }
  }
  return out;
}

std::vector<glm::dvec2> points_along(const std::vector<SvgStroke>& strokes, double step) {
  std::vector<glm::dvec2> points;
  for (const auto& [a, b] : segments_of(strokes)) {
    const int n = std::max(1, static_cast<int>(std::ceil(glm::length(b - a) / step)));
    for (int i = 0; i <= n; ++i) points.push_back(glm::mix(a, b, static_cast<double>(i) / n));
  }
  return points;
}

double covered_share(const SampledLine& line, const std::vector<std::pair<glm::dvec2, glm::dvec2>>& drawn,
                     double reach) {
  std::size_t seen = 0, covered = 0;
  for (std::size_t i = 0; i < line.at.size(); ++i) {
    if (!line.seen[i]) continue;
    ++seen;
    covered += distance_to(drawn, line.at[i]) <= reach;
  }
  return seen == 0 ? 1.0 : static_cast<double>(covered) / static_cast<double>(seen);
}

bool inside_hull(std::vector<glm::dvec2> points, glm::dvec2 p, double inset) {
  // Andrew's monotone chain, counter-clockwise.
  std::sort(points.begin(), points.end(), [](auto a, auto b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  const auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::dvec2> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const glm::dvec2& q : points) {
      while (hull.size() >= base + 2 && cross(hull[hull.size() - 2], hull.back(), q) <= 0) hull.pop_back();
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(points.begin(), points.end());
  }
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    const double len = glm::length(b - a);
    if (len == 0) continue;
    if (cross(a, b, p) / len < inset) return false;
  }
  return hull.size() >= 3;
}

}  // namespace toond::test
