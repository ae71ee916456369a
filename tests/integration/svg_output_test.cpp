// output svg through the daemon: the lines as vectors against analytic
// scenes (a cube, a small box before a bigger one, two boxes crossing, a
// torus), each drawn point laid over the exact lines through the camera
// the drawing's metadata holds; the same request's PNG lines layer against
// the SVG rasterised by librsvg on real models; and the requests around it
// (Accept, svg.hidden, svg fields on another output, a sheet).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "support/line_oracle.h"
#include "support/shared_models.h"
#include "support/svg_drawing.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;
using Segments = std::vector<std::pair<glm::dvec2, glm::dvec2>>;

// An OBJ of boxes, each with one normal a face (its sides crease).
std::string boxes_obj(const std::vector<Box>& boxes) {
  std::string obj = "vn -1 0 0\nvn 1 0 0\nvn 0 -1 0\nvn 0 1 0\nvn 0 0 -1\nvn 0 0 1\n";
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    for (int i = 0; i < 8; ++i) {
      const Box& box = boxes[b];
      obj += "v " + std::to_string(i & 1 ? box.hi.x : box.lo.x) + " " + std::to_string(i & 2 ? box.hi.y : box.lo.y) +
             " " + std::to_string(i & 4 ? box.hi.z : box.lo.z) + "\n";
    }
    const auto f = [&](int a, int c, int d, int e, int n) {
      const int o = static_cast<int>(8 * b) + 1;
      const std::string vn = "//" + std::to_string(n);
      obj += "f " + std::to_string(a + o) + vn + " " + std::to_string(c + o) + vn + " " + std::to_string(d + o) + vn +
             " " + std::to_string(e + o) + vn + "\n";
    };
    f(0, 4, 6, 2, 1);
    f(1, 3, 7, 5, 2);
    f(0, 1, 5, 4, 3);
    f(2, 6, 7, 3, 4);
    f(0, 2, 3, 1, 5);
    f(4, 5, 7, 6, 6);
  }
  return obj;
}

// A torus about the y axis with smooth normals.
std::string torus_obj(const Torus& torus, int around, int tube) {
  const double pi = std::acos(-1.0);
  std::string obj;
  for (int i = 0; i < around; ++i) {
    for (int k = 0; k < tube; ++k) {
      const double u = 2 * pi * i / around, v = 2 * pi * k / tube;
      const glm::dvec3 n(std::cos(v) * std::cos(u), std::sin(v), std::cos(v) * std::sin(u));
      const glm::dvec3 p = glm::dvec3(torus.major * std::cos(u), 0, torus.major * std::sin(u)) + torus.minor * n;
      obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
      obj += "vn " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n";
    }
  }
  const auto at = [&](int i, int k) { return std::to_string((i % around) * tube + (k % tube) + 1); };
  for (int i = 0; i < around; ++i) {
    for (int k = 0; k < tube; ++k) {
      const std::string a = at(i, k), b = at(i + 1, k), c = at(i + 1, k + 1), d = at(i, k + 1);
      obj += "f " + a + "//" + a + " " + d + "//" + d + " " + c + "//" + c + " " + b + "//" + b + "\n";
    }
  }
  return obj;
}

class SvgOutput : public SharedDaemonTest {
 protected:
  static httplib::Result post(const json& params, const httplib::Headers& headers = {}) {
    auto client = daemon().client();
    return client.Post("/render", headers, params.dump(), "application/json");
  }
  static SvgFile svg_of(const json& params) {
    auto res = post(params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << params.dump() << " answered "
                    << (res ? std::to_string(res->status) + ": " + res->body : "nothing");
      return {};
    }
    EXPECT_EQ(res->get_header_value("Content-Type"), "image/svg+xml");
    return read_svg_drawing(res->body);
  }
  static std::string upload(const std::string& obj, const std::string& name) {
    auto client = daemon().client();
    return upload_obj_text(client, obj, name);
  }
};

// Every drawn point's distance to the seen stretches: the largest, and how
// many lie farther than `reach`.
struct Stray {
  double worst = 0;
  std::size_t outliers = 0;
  std::size_t points = 0;
};
Stray stray_of(const std::vector<glm::dvec2>& drawn, const Segments& seen, double reach) {
  Stray s;
  for (const glm::dvec2& p : drawn) {
    const double d = distance_to(seen, p);
    s.worst = std::max(s.worst, d);
    s.outliers += d > reach;
    ++s.points;
  }
  return s;
}

std::vector<SvgStroke> all_strokes(const SvgFile& svg, const std::vector<std::string>& layers) {
  std::vector<SvgStroke> out;
  for (const std::string& id : layers) {
    if (!svg.layers.count(id)) continue;
    const auto& s = svg.layers.at(id).strokes;
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

const std::vector<std::string> kVisibleLayers = {"silhouette", "creases", "intersections", "boundary"};

// The exact lines of a scene laid over a drawing: every drawn point within
// 1 px of a seen stretch of one, every line that ought to be drawn (more
// than half of it) at least 98 % covered by its layer's strokes within
// 1 px, and no stroke within 1 px of a hidden stretch that lies 2 px or
// more from every seen one. A silhouette ought to be drawn where it is the
// outline, as the default hull draws it: the ray 2 px beyond it (half the
// stroke and a pixel), away from its face turned toward the eye, meets
// nothing (`meets`); elsewhere it is not drawn.
struct ExactLine {
  glm::dvec3 a, b;
  std::string layer;     // where it belongs while seen
  glm::dvec3 face{0.0};  // a silhouette's: a point of its face turned toward the eye
};
using Meets = std::function<bool(glm::dvec2)>;

// Per sample of a line, whether it ought to be drawn.
std::vector<bool> ought_drawn(const ExactLine& line, const SampledLine& sampled, const MetaCamera& camera,
                              const Meets& meets) {
  std::vector<bool> ought = sampled.seen;
  if (line.layer != "silhouette") return ought;
  const glm::dvec2 a = camera.project(line.a), b = camera.project(line.b);
  glm::dvec2 away = glm::normalize(glm::dvec2(a.y - b.y, b.x - a.x));
  if (glm::dot(away, camera.project(line.face) - a) > 0) away = -away;
  for (std::size_t k = 0; k < ought.size(); ++k) ought[k] = ought[k] && !meets(sampled.at[k] + 2.0 * away);
  return ought;
}

void expect_lines_match(const SvgFile& svg, const std::vector<ExactLine>& lines,
                        const std::function<bool(const glm::dvec3&)>& seen, const Meets& meets,
                        const std::string& what) {
  const MetaCamera camera = camera_from_metadata(svg.camera);
  std::vector<SampledLine> sampled, ought;
  for (const ExactLine& line : lines) {
    sampled.push_back(sample_line(camera, line.a, line.b, seen, 400));
    ought.push_back(sampled.back());
    ought.back().seen = ought_drawn(line, sampled.back(), camera, meets);
  }
  const Segments seen_parts = seen_stretches(sampled), ought_parts = seen_stretches(ought);
  const Segments drawn = segments_of(all_strokes(svg, kVisibleLayers));
  const Stray stray = stray_of(points_along(all_strokes(svg, kVisibleLayers), 0.5), seen_parts, 1.0);
  EXPECT_EQ(stray.outliers, 0u) << what << ": of " << stray.points << " drawn points " << stray.outliers
                                << " lie over 1 px from every seen line, the farthest " << stray.worst << " px";
  std::size_t not_outline = 0, not_outline_drawn = 0, hidden_samples = 0, hidden_drawn = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (ought[i].seen_share() >= 0.5) {
      const double covered = covered_share(ought[i], segments_of(all_strokes(svg, {lines[i].layer})), 1.0);
      EXPECT_GE(covered, 0.98) << what << ": line " << i << " ought to be drawn along " << 100 * ought[i].seen_share()
                               << " % but only " << 100 * covered << " % of that is, in " << lines[i].layer;
    }
    for (std::size_t k = 0; k < sampled[i].at.size(); ++k) {
      const glm::dvec2 p = sampled[i].at[k];
      if (sampled[i].seen[k] && !ought[i].seen[k] && distance_to(ought_parts, p) >= 3.0) {
        ++not_outline;
        not_outline_drawn += distance_to(drawn, p) <= 1.0;
      }
      if (!sampled[i].seen[k] && distance_to(seen_parts, p) >= 2.0) {
        ++hidden_samples;
        hidden_drawn += distance_to(drawn, p) <= 1.0;
      }
    }
  }
  EXPECT_EQ(not_outline_drawn, 0u) << what << ": " << not_outline_drawn << " of " << not_outline
                                   << " seen silhouette samples off the outline (3 px or more from it) are drawn";
  EXPECT_EQ(hidden_drawn, 0u) << what << ": " << hidden_drawn << " of " << hidden_samples
                              << " hidden samples (2 px or more from any seen line) have a stroke within 1 px";
}

// A box's edges, each in the layer it belongs to from this camera: the
// silhouette where one of its two faces turns away, else the creases.
std::vector<ExactLine> box_lines(const Box& box, const MetaCamera& camera) {
  std::vector<ExactLine> lines;
  const glm::dvec3 centre = 0.5 * (box.lo + box.hi);
  for (const auto& [a, b] : box_edges(box)) {
    int turned_away = 0;
    glm::dvec3 face(0.0);
    // The edge's two faces: in the planes across the two axes it does not run along.
    for (int k = 0; k < 3; ++k) {
      if (a[k] != b[k]) continue;
      glm::dvec3 n(0.0);
      n[k] = a[k] > centre[k] ? 1.0 : -1.0;
      const glm::dvec3 toward_eye = camera.orthographic ? -camera.forward : camera.eye - a;
      if (glm::dot(n, toward_eye) <= 0) {
        ++turned_away;
        continue;
      }
      // That face's middle along the edge: the edge's middle moved across
      // the face (along its other axis) to the box's centre.
      face = 0.5 * (a + b);
      for (int j = 0; j < 3; ++j) {
        if (j != k && a[j] == b[j]) face[j] = centre[j];
      }
    }
    lines.push_back({a, b, turned_away == 1 ? "silhouette" : "creases", face});
  }
  return lines;
}

TEST_F(SvgOutput, ACubesNineVisibleEdgesAndNotItsThreeHiddenOnes) {
  const Box cube{{-1, -1, -1}, {1, 1, 1}};
  const std::string id = upload(boxes_obj({cube}), "cube.obj");
  for (const char* projection : {"perspective", "orthographic"}) {
    const SvgFile svg = svg_of(
        {{"model", id}, {"output", "svg"}, {"camera", {{"yaw", 30}, {"pitch", 25}, {"projection", projection}}}});
    ASSERT_FALSE(svg.camera.is_null()) << projection;
    const MetaCamera camera = camera_from_metadata(svg.camera);
    const std::vector<ExactLine> lines = box_lines(cube, camera);
    const auto seen = [&](const glm::dvec3& p) { return seen_among_boxes(camera, {cube}, p); };
    std::size_t outline = 0, inner = 0, hidden = 0;
    for (const ExactLine& line : lines) {
      // A hidden edge's ends may be seen (a corner on the outline).
      const double share = sample_line(camera, line.a, line.b, seen, 100).seen_share();
      if (share < 0.05) ++hidden;
      if (share > 0.95) ++(line.layer == "silhouette" ? outline : inner);
    }
    ASSERT_EQ(outline, 6u) << projection;
    ASSERT_EQ(inner, 3u) << projection;
    ASSERT_EQ(hidden, 3u) << projection;
    const Meets meets = [&](glm::dvec2 px) { return ray_meets_boxes(camera, {cube}, px); };
    expect_lines_match(svg, lines, seen, meets, std::string("cube, ") + projection);
    EXPECT_LE(svg.path_data.size(), 6u) << projection;
    EXPECT_EQ(svg.layers.at("silhouette").attributes.at("inkscape:groupmode"), "layer");
    EXPECT_EQ(svg.layers.at("silhouette").strokes.size(), 1u) << projection << ": the outline is one loop";
  }
}

// A small box in front of a bigger one, as two objects of a scene: none of
// the bigger box's lines shows through the smaller one, seen from the left
// or from the right.
TEST_F(SvgOutput, ABoxInFrontHidesTheLinesBehindIt) {
  const std::string id = upload(boxes_obj({{{-1, -1, -1}, {1, 1, 1}}}), "unit_cube.obj");
  const Box big{{-1, -1, -1}, {1, 1, 1}};
  const Box small{{-0.3, -0.3, 1.2}, {0.3, 0.3, 1.8}};
  const json objects = {
      {{"model", id}},
      {{"model", id}, {"transform", {{"translate", {0, 0, 1.5}}, {"scale", 0.3}}}},
  };
  for (int yaw : {-25, 25}) {
    const SvgFile svg = svg_of({{"objects", objects}, {"output", "svg"}, {"camera", {{"yaw", yaw}, {"pitch", 15}}}});
    ASSERT_FALSE(svg.camera.is_null());
    const MetaCamera camera = camera_from_metadata(svg.camera);
    const auto seen = [&](const glm::dvec3& p) { return seen_among_boxes(camera, {big, small}, p); };
    std::vector<ExactLine> lines = box_lines(big, camera);
    const std::vector<ExactLine> front = box_lines(small, camera);
    lines.insert(lines.end(), front.begin(), front.end());
    const Meets meets = [&](glm::dvec2 px) { return ray_meets_boxes(camera, {big, small}, px); };
    expect_lines_match(svg, lines, seen, meets, "yaw " + std::to_string(yaw));
    // Inside the small box's outline (1.5 px in from it), every drawn point
    // is the small box's own.
    std::vector<SampledLine> own;
    for (const ExactLine& line : front) own.push_back(sample_line(camera, line.a, line.b, seen, 400));
    const Segments own_lines = seen_stretches(own);
    std::vector<glm::dvec2> corners;
    for (const ExactLine& line : front) corners.push_back(camera.project(line.a));
    std::size_t inside = 0, foreign = 0;
    for (const glm::dvec2& p : points_along(all_strokes(svg, kVisibleLayers), 0.5)) {
      if (!inside_hull(corners, p, 1.5)) continue;
      ++inside;
      foreign += distance_to(own_lines, p) > 1.0;
    }
    EXPECT_GT(inside, 0u);
    EXPECT_EQ(foreign, 0u) << "yaw " << yaw << ": drawn points of the bigger box inside the smaller one's outline";
  }
}

// Two boxes passing through each other: where the thin one goes into the
// big one's faces, the seams (two squares) are drawn in `intersections`,
// the one in front where the thin box does not hide it, the one behind not
// at all. As one model (its seams found at import) and as two objects of a
// scene (found for the frame: no import saw them cross).
TEST_F(SvgOutput, TwoCrossingBoxesDrawTheirSeam) {
  const Box big{{-1, -1, -1}, {1, 1, 1}};
  const Box rod{{-0.4, -0.4, -1.7}, {0.4, 0.4, 1.7}};
  const json one_model = {{"model", upload(boxes_obj({big, rod}), "crossing.obj")}};
  const std::string cube = upload(boxes_obj({big}), "unit_cube.obj");
  const json scene = {{"objects", {{{"model", cube}}, {{"model", cube}, {"transform", {{"scale", {0.4, 0.4, 1.7}}}}}}}};
  for (const auto& [form, drawn] : {std::pair("one model", one_model), std::pair("a scene", scene)})
    for (const char* projection : {"perspective", "orthographic"}) {
      json request = drawn;
      request["output"] = "svg";
      request["camera"] = {{"yaw", 30}, {"pitch", 25}, {"projection", projection}};
      const SvgFile svg = svg_of(request);
      ASSERT_FALSE(svg.camera.is_null()) << form;
      const MetaCamera camera = camera_from_metadata(svg.camera);
      const auto seen = [&](const glm::dvec3& p) { return seen_among_boxes(camera, {big, rod}, p); };
      std::vector<ExactLine> lines = box_lines(big, camera);
      const std::vector<ExactLine> rod_lines = box_lines(rod, camera);
      lines.insert(lines.end(), rod_lines.begin(), rod_lines.end());
      std::size_t seams_seen = 0;
      for (double z : {-1.0, 1.0}) {
        const glm::dvec3 c[4] = {{-0.4, -0.4, z}, {0.4, -0.4, z}, {0.4, 0.4, z}, {-0.4, 0.4, z}};
        for (int k = 0; k < 4; ++k) {
          lines.push_back({c[k], c[(k + 1) % 4], "intersections"});
          seams_seen += sample_line(camera, c[k], c[(k + 1) % 4], seen, 100).seen_share() > 0.5;
        }
      }
      EXPECT_GE(seams_seen, 2u) << projection << ": the front square's near sides show";
      const std::string what = std::string(form) + ", " + projection;
      // The rod's long edges run through the big box: the stretch inside it
      // is no line (ray casting sees it hidden; it lies inside a solid).
      const Meets meets = [&](glm::dvec2 px) { return ray_meets_boxes(camera, {big, rod}, px); };
      expect_lines_match(svg, lines, seen, meets, what);
      EXPECT_FALSE(svg.layers.at("intersections").strokes.empty()) << what;
    }
}

// A smooth torus, whose contour (where its surface turns edge-on to the eye)
// is found exactly from the torus itself: with the back-face wireframe
// every seen piece of it is the silhouette layer; with the default hull,
// those where nothing lies just beyond them (the outer outline and the
// hole's), not those over the torus's own far side.
// Within kCuspReach px of a seen cusp the contour of the facets parts from
// the smooth one (a 256 × 128 torus: 1.9 px at most, 3.4 at 128 × 64):
// there neither is held to the other.
constexpr double kCuspReach = 4.0;
struct TorusContour {
  std::vector<glm::dvec2> seen, outline, over_itself, cusps;
};
TorusContour torus_contour_seen(const MetaCamera& camera, const Torus& torus, double reach_px) {
  TorusContour c;
  const TorusContourPoints contour = torus_contour(camera, torus, 4000);
  for (const glm::dvec3& p : contour.cusps) {
    if (seen_on_torus(camera, torus, p)) c.cusps.push_back(camera.project(p));
  }
  for (const glm::dvec3& p : contour.points) {
    if (!seen_on_torus(camera, torus, p)) continue;
    const glm::dvec2 at = camera.project(p);
    bool near_cusp = false;
    for (const glm::dvec2& cusp : c.cusps) near_cusp |= glm::length(cusp - at) < kCuspReach;
    if (near_cusp) continue;
    const glm::dvec2 out = camera.project(p + 1e-3 * torus_normal(torus, p)) - at;
    c.seen.push_back(at);
    const bool beyond = ray_meets_torus(camera, torus, at + reach_px * out / glm::length(out));
    (beyond ? c.over_itself : c.outline).push_back(at);
  }
  return c;
}

Segments as_points(const std::vector<glm::dvec2>& points) {
  Segments out;
  for (const glm::dvec2& p : points) out.emplace_back(p, p);
  return out;
}

double share_within(const std::vector<glm::dvec2>& points, const Segments& drawn, double reach) {
  std::size_t near = 0;
  for (const glm::dvec2& p : points) near += distance_to(drawn, p) <= reach;
  return points.empty() ? 1.0 : static_cast<double>(near) / static_cast<double>(points.size());
}

TEST_F(SvgOutput, ATorusContourIsItsSilhouette) {
  const Torus torus;
  const std::string id = upload(torus_obj(torus, 256, 128), "torus.obj");
  for (const char* projection : {"perspective", "orthographic"}) {
    for (const char* method : {"wireframe", "hull"}) {
      const std::string what = std::string(projection) + ", " + method;
      const SvgFile svg = svg_of({{"model", id},
                                  {"output", "svg"},
                                  {"outline", {{"method", method}}},
                                  {"camera", {{"yaw", 20}, {"pitch", 20}, {"projection", projection}}}});
      ASSERT_FALSE(svg.camera.is_null()) << what;
      const MetaCamera camera = camera_from_metadata(svg.camera);
      const TorusContour contour = torus_contour_seen(camera, torus, 2.0);
      ASSERT_GT(contour.outline.size(), 2000u) << what;
      ASSERT_GT(contour.over_itself.size(), 200u) << what << ": the view shows contour over the torus itself";
      const std::vector<SvgStroke>& strokes = svg.layers.at("silhouette").strokes;
      std::vector<glm::dvec2> clear_of_cusps;
      for (const glm::dvec2& p : points_along(strokes, 0.5)) {
        if (distance_to(as_points(contour.cusps), p) >= kCuspReach) clear_of_cusps.push_back(p);
      }
      const std::size_t drawn_points = points_along(strokes, 0.5).size();
      EXPECT_GT(clear_of_cusps.size(), drawn_points * 95 / 100) << what << ": the cusps' neighbourhoods are small";
      std::cout << what << ": " << contour.cusps.size() << " seen cusps; " << drawn_points - clear_of_cusps.size()
                << " of " << drawn_points << " drawn points within " << kCuspReach << " px of one\n";
      const Stray stray = stray_of(clear_of_cusps, as_points(contour.seen), 1.0);
      EXPECT_EQ(stray.outliers, 0u) << what << ": of " << stray.points << " drawn points " << stray.outliers
                                    << " lie over 1 px from the seen contour, the farthest " << stray.worst << " px";
      const Segments drawn = segments_of(strokes);
      EXPECT_GE(share_within(contour.outline, drawn, 1.0), 0.98) << what << ": the outline";
      if (std::string(method) == "wireframe") {
        EXPECT_GE(share_within(contour.over_itself, drawn, 1.0), 0.98) << what << ": the contour over the torus";
      } else {
        // Contour over the torus, 3 px or more from the outline, is not drawn.
        std::vector<glm::dvec2> clear_of_outline;
        const Segments outline = as_points(contour.outline);
        for (const glm::dvec2& p : contour.over_itself) {
          if (distance_to(outline, p) >= 3.0) clear_of_outline.push_back(p);
        }
        EXPECT_EQ(share_within(clear_of_outline, drawn, 1.0), 0.0) << what << ": contour over the torus drawn";
      }
      for (const char* other : {"creases", "intersections", "boundary"}) {
        EXPECT_TRUE(svg.layers.at(other).strokes.empty()) << what << ": " << other;
      }
    }
  }
}

// Where the SVG's strokes, rasterised by librsvg, and the same request's
// PNG lines layer put ink (alpha at least half): each's share within 3 px
// of the other's.
struct InkAgreement {
  std::size_t svg_ink = 0, png_ink = 0;
  double svg_near_png = 0, png_near_svg = 0;
};

std::vector<bool> ink_of(const image::Image& image) {
  std::vector<bool> ink(static_cast<std::size_t>(image.width) * image.height);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x)
      ink[static_cast<std::size_t>(y) * image.width + x] = image.pixel(x, y)[3] >= 128;
  }
  return ink;
}

// The share of `from`'s ink with some of `to`'s within `reach` pixels.
double share_near(const std::vector<bool>& from, const std::vector<bool>& to, int width, int height, int reach) {
  std::size_t ink = 0, near = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!from[static_cast<std::size_t>(y) * width + x]) continue;
      ++ink;
      bool found = false;
      for (int dy = -reach; dy <= reach && !found; ++dy) {
        for (int dx = -reach; dx <= reach && !found; ++dx) {
          const int u = x + dx, v = y + dy;
          if (dx * dx + dy * dy > reach * reach || u < 0 || v < 0 || u >= width || v >= height) continue;
          found = to[static_cast<std::size_t>(v) * width + u];
        }
      }
      near += found;
    }
  }
  return ink == 0 ? 0.0 : static_cast<double>(near) / static_cast<double>(ink);
}

InkAgreement agreement(const image::Image& svg_raster, const image::Image& png) {
  const std::vector<bool> a = ink_of(svg_raster), b = ink_of(png);
  InkAgreement out;
  out.svg_ink = static_cast<std::size_t>(std::count(a.begin(), a.end(), true));
  out.png_ink = static_cast<std::size_t>(std::count(b.begin(), b.end(), true));
  out.svg_near_png = share_near(a, b, png.width, png.height, 3);
  out.png_near_svg = share_near(b, a, png.width, png.height, 3);
  return out;
}

constexpr const char* kRsvgConvert = "/usr/bin/rsvg-convert";

bool have_rsvg() { return std::filesystem::exists(kRsvgConvert); }

// The SVG through librsvg's rsvg-convert, at its own size.
image::Image rasterise(const std::string& svg) {
  const auto dir = make_temp_dir("toond-svg");
  std::ofstream(dir / "lines.svg", std::ios::binary) << svg;
  const auto r = run_process({kRsvgConvert, "-o", (dir / "lines.png").string(), (dir / "lines.svg").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  std::ifstream in(dir / "lines.png", std::ios::binary);
  const std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove_all(dir);
  return image::decode_png(png);
}

class SvgAgainstLines : public SvgOutput {
 protected:
  // One request drawn twice, as output svg and as output lines.
  struct Drawn {
    std::string svg;
    std::string stats;  // the SVG's X-Toond-Lines
    image::Image lines;
  };
  static std::optional<Drawn> svg_and_lines(const json& request) {
    json as_svg = request, as_lines = request;
    as_svg["output"] = "svg";
    as_lines["output"] = "lines";
    auto svg = post(as_svg);
    if (!svg || svg->status != 200) {
      ADD_FAILURE() << as_svg.dump() << " answered " << (svg ? svg->body : "nothing");
      return std::nullopt;
    }
    auto client = daemon().client();
    return Drawn{svg->body, svg->get_header_value("X-Toond-Lines"), render_ok(client, as_lines)};
  }

  // The model's SVG and lines layer, the same request but for output.
  void expect_agreement(const std::string& id, const std::string& what) {
    if (!have_rsvg()) GTEST_SKIP() << "rsvg-convert (librsvg2-bin) is not installed";
    for (const json& camera : {json{{"yaw", 30}, {"pitch", 15}}, json{{"yaw", -120}, {"pitch", 30}}}) {
      const std::optional<Drawn> drawn = svg_and_lines({{"model", id}, {"camera", camera}});
      ASSERT_TRUE(drawn);
      const InkAgreement a = agreement(rasterise(drawn->svg), drawn->lines);
      EXPECT_GE(a.svg_near_png, 0.95) << what << " " << camera.dump() << ": SVG ink " << a.svg_ink << " px";
      EXPECT_GE(a.png_near_svg, 0.95) << what << " " << camera.dump() << ": PNG ink " << a.png_ink << " px";
      std::cout << what << " " << camera.dump() << ": " << 100 * a.svg_near_png << " % of the SVG's " << a.svg_ink
                << " ink px near the PNG's, " << 100 * a.png_near_svg << " % of the PNG's " << a.png_ink
                << " near the SVG's; " << drawn->stats << "\n";
    }
  }
};

TEST_F(SvgAgainstLines, Bunny) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  auto res = upload_model_folder(client, shared_models_dir() / "stanford-bunny");
  ASSERT_TRUE(res && res->status / 100 == 2);
  expect_agreement(json::parse(res->body)["id"], "bunny");
}

TEST_F(SvgAgainstLines, Spot) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  auto res = upload_model_folder(client, shared_models_dir() / "spot");
  ASSERT_TRUE(res && res->status / 100 == 2);
  expect_agreement(json::parse(res->body)["id"], "spot");
}

// CGAL's fandisk: curved patches meeting at sharp creases.
TEST_F(SvgAgainstLines, Fandisk) {
  auto client = daemon().client();
  auto res = upload_files(client, TOOND_EXPORTED_DIR "/cgal", {"fandisk.off"});
  ASSERT_TRUE(res && res->status / 100 == 2) << (res ? res->body : "no answer");
  expect_agreement(json::parse(res->body)["id"], "fandisk");
}

// A pose: Blender's walking character (tests/exported/blender/make_walker.py)
// at two times of its Walk, each SVG against its own PNG lines layer: the
// drawing follows the posed vertices, not the rest ones.
TEST_F(SvgAgainstLines, PosedWalker) {
  if (!have_rsvg()) GTEST_SKIP() << "rsvg-convert (librsvg2-bin) is not installed";
  auto client = daemon().client();
  auto res = upload_files(client, TOOND_EXPORTED_DIR "/blender", {"walker.glb"});
  ASSERT_TRUE(res && res->status / 100 == 2) << (res ? res->body : "no answer");
  const std::string id = json::parse(res->body)["id"];
  std::vector<std::string> drawings;
  for (double time : {0.1, 0.5}) {
    const std::optional<Drawn> drawn = svg_and_lines(
        {{"model", id}, {"camera", {{"yaw", 60}, {"pitch", 10}}}, {"animation", {{"clip", "Walk"}, {"time", time}}}});
    ASSERT_TRUE(drawn);
    const InkAgreement a = agreement(rasterise(drawn->svg), drawn->lines);
    EXPECT_GE(a.svg_near_png, 0.95) << "time " << time << ": SVG ink " << a.svg_ink << " px";
    EXPECT_GE(a.png_near_svg, 0.95) << "time " << time << ": PNG ink " << a.png_ink << " px";
    std::cout << "walker at " << time << " s: " << 100 * a.svg_near_png << " % of the SVG's " << a.svg_ink
              << " ink px near the PNG's, " << 100 * a.png_near_svg << " % of the PNG's " << a.png_ink
              << " near the SVG's\n";
    drawings.push_back(drawn->svg);
  }
  EXPECT_NE(drawings[0], drawings[1]) << "two times of the walk draw alike";
}

// Of the SVG's pixels inked through (alpha 255), the share with an ink
// pixel of the PNG (alpha at least half) within `reach` px whose colour
// lies within `tolerance` of it in every sRGB channel.
double colour_agreement(const image::Image& svg, const image::Image& png, int reach, int tolerance) {
  std::size_t inked = 0, matched = 0;
  for (int y = 0; y < svg.height; ++y) {
    for (int x = 0; x < svg.width; ++x) {
      const std::uint8_t* a = svg.pixel(x, y);
      if (a[3] < 255) continue;
      ++inked;
      bool found = false;
      for (int dy = -reach; dy <= reach && !found; ++dy) {
        for (int dx = -reach; dx <= reach && !found; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= png.width || v >= png.height || png.pixel(u, v)[3] < 128) continue;
          const std::uint8_t* b = png.pixel(u, v);
          found = std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance &&
                  std::abs(a[2] - b[2]) <= tolerance;
        }
      }
      matched += found;
    }
  }
  return inked == 0 ? 0.0 : static_cast<double>(matched) / static_cast<double>(inked);
}

// The colours a layer's strokes are drawn in.
std::set<std::string> stroke_colours(const SvgLayer& layer) {
  std::set<std::string> out;
  for (const SvgStroke& s : layer.strokes) out.insert(s.colour);
  return out;
}

// "#rrggbb" of a linear colour, as toond writes it.
std::string hex_of_linear(const glm::dvec3& linear) {
  const auto byte = [](double c) {
    const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(std::clamp(s, 0.0, 1.0) * 255.0));
  };
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", byte(linear.r), byte(linear.g), byte(linear.b));
  return buffer;
}

// Every Kd of an MTL file (linear, as toond reads them).
std::vector<glm::dvec3> diffuse_colours(const std::filesystem::path& mtl) {
  std::ifstream in(mtl);
  std::vector<glm::dvec3> out;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string key;
    glm::dvec3 kd;
    if (words >> key && key == "Kd" && words >> kd.r >> kd.g >> kd.b) out.push_back(kd);
  }
  return out;
}

// outline.color_mode material on Kenney's space craft (Kd colours, no
// texture): each silhouette takes its material's colour darkened, exactly
// the MTL's Kd × (1 - darken); crease lines keep the outline's colour, as
// the PNG draws them; and the SVG rasterised has the PNG's colours where
// their lines lie.
TEST_F(SvgAgainstLines, MaterialColourModeColoursEachSilhouetteByItsMaterial) {
  TOOND_REQUIRE_SHARED_MODELS();
  if (!have_rsvg()) GTEST_SKIP() << "rsvg-convert (librsvg2-bin) is not installed";
  const auto folder = shared_models_dir() / "kenney-space-craft";
  auto client = daemon().client();
  auto res = upload_model_folder(client, folder);
  ASSERT_TRUE(res && res->status / 100 == 2);
  std::set<std::string> materials;
  for (const glm::dvec3& kd : diffuse_colours(folder / "craft_speederA.mtl")) materials.insert(hex_of_linear(kd * 0.4));
  // A pure blue outline colour, which no material darkened gives.
  const std::optional<Drawn> drawn =
      svg_and_lines({{"model", json::parse(res->body)["id"]},
                     {"camera", {{"yaw", 35}, {"pitch", 25}}},
                     {"outline", {{"color_mode", "material"}, {"darken", 0.6}, {"width", 3}, {"color", {0, 0, 1}}}}});
  ASSERT_TRUE(drawn);
  const SvgFile file = read_svg_drawing(drawn->svg);
  const std::set<std::string> silhouette_colours = stroke_colours(file.layers.at("silhouette"));
  EXPECT_GE(silhouette_colours.size(), 2u) << "one colour for every material";
  for (const std::string& colour : silhouette_colours) {
    EXPECT_TRUE(materials.count(colour)) << colour << " is no material's Kd darkened";
  }
  EXPECT_EQ(file.layers.at("creases").attributes.at("stroke"), "#0000ff");
  ASSERT_FALSE(file.layers.at("creases").strokes.empty());
  EXPECT_EQ(stroke_colours(file.layers.at("creases")), std::set<std::string>{"#0000ff"}) << "crease lines";
  const double share = colour_agreement(rasterise(drawn->svg), drawn->lines, 2, 24);
  EXPECT_GE(share, 0.9) << "of the SVG's ink has the PNG's colour nearby";
  std::cout << "space craft, material colours: " << silhouette_colours.size() << " silhouette colours; " << 100 * share
            << " % of the SVG's ink has the PNG's colour within 2 px\n";
}

// outline.color_mode texture on Spot: the silhouette takes the texture
// beside it, inverted and darkened, as the PNG's hull draws it.
TEST_F(SvgAgainstLines, TextureColourModeColoursTheSilhouetteByTheTexture) {
  TOOND_REQUIRE_SHARED_MODELS();
  if (!have_rsvg()) GTEST_SKIP() << "rsvg-convert (librsvg2-bin) is not installed";
  auto client = daemon().client();
  auto res = upload_model_folder(client, shared_models_dir() / "spot");
  ASSERT_TRUE(res && res->status / 100 == 2);
  const std::optional<Drawn> drawn =
      svg_and_lines({{"model", json::parse(res->body)["id"]},
                     {"camera", {{"yaw", 30}, {"pitch", 15}}},
                     {"outline", {{"color_mode", "texture"}, {"darken", 0.3}, {"width", 3}}}});
  ASSERT_TRUE(drawn);
  const SvgFile file = read_svg_drawing(drawn->svg);
  const std::set<std::string> colours = stroke_colours(file.layers.at("silhouette"));
  EXPECT_GE(colours.size(), 2u) << "the texture varies along the outline";
  const double share = colour_agreement(rasterise(drawn->svg), drawn->lines, 2, 40);
  EXPECT_GE(share, 0.8) << "of the SVG's ink has the PNG's colour nearby";
  std::cout << "spot, texture colours: " << colours.size() << " colours in "
            << file.layers.at("silhouette").strokes.size() << " silhouette strokes; " << 100 * share
            << " % of the SVG's ink has the PNG's colour within 2 px\n";
}

// An OBJ of n×n separate squares in the xy plane, one unit apart, each
// 0.6 wide: every square's four sides are open edges, all seen face on.
std::string squares_obj(int n) {
  std::string obj;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < n; ++k) {
      const double x = i - 0.5 * n, y = k - 0.5 * n;
      for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, {0.6, 0.0}, {0.6, 0.6}, {0.0, 0.6}}) {
        obj += "v " + std::to_string(x + dx) + " " + std::to_string(y + dy) + " 0\n";
      }
      const int o = 4 * (i * n + k) + 1;
      obj += "f " + std::to_string(o) + " " + std::to_string(o + 1) + " " + std::to_string(o + 2) + " " +
             std::to_string(o + 3) + "\n";
    }
  }
  return obj;
}

// A drawing larger than a megabyte goes out as it is written, in chunks:
// no Content-Length, no ETag (nothing hashed it), not kept for the next
// identical request; the text is whole and every square is one closed
// path. A small drawing keeps its length and ETag.
TEST_F(SvgOutput, ALargeDrawingIsStreamedInChunks) {
  const int n = 150;
  const std::string id = upload(squares_obj(n), "squares.obj");
  const json request = {{"model", id},
                        {"output", "svg"},
                        {"width", 2048},
                        {"height", 2048},
                        {"outline", {{"method", "wireframe"}, {"width", 1}}},
                        {"camera", {{"yaw", 0}, {"pitch", 0}, {"projection", "orthographic"}}}};
  for (int attempt = 0; attempt < 2; ++attempt) {
    auto res = post(request);
    ASSERT_TRUE(res && res->status == 200) << (res ? res->body : "no answer");
    EXPECT_EQ(res->get_header_value("Transfer-Encoding"), "chunked");
    EXPECT_FALSE(res->has_header("Content-Length"));
    EXPECT_FALSE(res->has_header("ETag"));
    EXPECT_FALSE(res->has_header("X-Toond-Cache")) << "a streamed drawing is drawn again";
    EXPECT_GT(res->body.size(), std::size_t{1} << 20);
    const SvgFile svg = read_svg_drawing(res->body);
    EXPECT_NE(res->body.find("</svg>\n"), std::string::npos);
    std::size_t squares = 0;
    for (const SvgStroke& s : svg.layers.at("boundary").strokes) squares += s.closed && s.points.size() == 4;
    EXPECT_EQ(squares, static_cast<std::size_t>(n * n)) << "of " << svg.layers.at("boundary").strokes.size();
    if (attempt == 0) std::cout << "squares: " << res->body.size() / 1024 << " KiB, streamed\n";
  }
  const std::string cube = upload(boxes_obj({{{-1, -1, -1}, {1, 1, 1}}}), "cube.obj");
  auto small = post({{"model", cube}, {"output", "svg"}});
  ASSERT_TRUE(small && small->status == 200);
  EXPECT_TRUE(small->has_header("Content-Length"));
  EXPECT_TRUE(small->has_header("ETag"));
}

TEST_F(SvgOutput, AcceptHeaderAsksForSvgWhenNoOutputIsGiven) {
  auto res = post({{"width", 128}, {"height", 128}}, {{"Accept", "image/svg+xml"}});
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "image/svg+xml");
  EXPECT_NO_THROW(read_svg_drawing(res->body));
  // An output given wins; a client that takes PNG too gets the PNG.
  auto png = post({{"width", 128}, {"height", 128}, {"output", "lines"}}, {{"Accept", "image/svg+xml"}});
  ASSERT_TRUE(png);
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  auto both = post({{"width", 128}, {"height", 128}}, {{"Accept", "image/svg+xml, image/png"}});
  ASSERT_TRUE(both);
  EXPECT_EQ(both->get_header_value("Content-Type"), "image/png");
}

// svg.hidden: the cube's three hidden edges, dashed, under the others.
TEST_F(SvgOutput, HiddenLayerHoldsTheHiddenEdges) {
  const Box cube{{-1, -1, -1}, {1, 1, 1}};
  const std::string id = upload(boxes_obj({cube}), "cube.obj");
  const SvgFile svg =
      svg_of({{"model", id}, {"output", "svg"}, {"svg", {{"hidden", true}}}, {"camera", {{"yaw", 30}, {"pitch", 25}}}});
  ASSERT_EQ(svg.layers.count("hidden"), 1u);
  const SvgLayer& hidden = svg.layers.at("hidden");
  EXPECT_TRUE(hidden.attributes.count("stroke-dasharray"));
  const MetaCamera camera = camera_from_metadata(svg.camera);
  const Segments dashed = segments_of(hidden.strokes);
  const auto seen = [&](const glm::dvec3& p) { return seen_among_boxes(camera, {cube}, p); };
  std::size_t hidden_edges = 0;
  for (const ExactLine& line : box_lines(cube, camera)) {
    const SampledLine sampled = sample_line(camera, line.a, line.b, seen, 200);
    if (sampled.seen_share() > 0.05) continue;  // its ends may be seen
    ++hidden_edges;
    std::size_t near = 0;
    for (const glm::dvec2& p : sampled.at) near += distance_to(dashed, p) <= 1.0;
    EXPECT_GE(static_cast<double>(near) / sampled.at.size(), 0.98);
  }
  EXPECT_EQ(hidden_edges, 3u);
  // Without it, no hidden layer.
  EXPECT_EQ(svg_of({{"model", id}, {"output", "svg"}}).layers.count("hidden"), 0u);
}

TEST_F(SvgOutput, SvgFieldsOnAnotherOutputNameTheField) {
  auto res = post({{"output", "lines"}, {"svg", {{"hidden", true}}}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 400);
  EXPECT_EQ(error_of(res)["path"], "/svg/hidden");
  auto color = post({{"svg", json::object()}});
  ASSERT_TRUE(color);
  EXPECT_EQ(color->status, 400);
  EXPECT_EQ(error_of(color)["path"], "/svg");
  auto sheet = post({{"output", "svg"}, {"sheet", {{"frames", 4}}}});
  ASSERT_TRUE(sheet);
  EXPECT_EQ(sheet->status, 400);
  EXPECT_EQ(error_of(sheet)["path"], "/sheet");
}

// A drawing priced over --max-render-cost is refused as any render is,
// with what would fit.
TEST(SvgOutputLimits, PricedOverTheLimitIsRefusedWithWhatWouldFit) {
  Daemon daemon({}, {"--max-render-cost", "1"});
  auto client = daemon.client();
  const std::string id = upload_obj_text(client, sphere_obj(256, 128), "dense.obj");
  auto res = client.Post("/render", json{{"model", id}, {"output", "svg"}}.dump(), "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422) << res->body;
  const json error = error_of(res);
  EXPECT_NE(error["message"].get<std::string>().find("line drawing"), std::string::npos) << error.dump();
  EXPECT_NE(error["message"].get<std::string>().find("outline.enabled false"), std::string::npos) << error.dump();
}

}  // namespace
}  // namespace toond::test
