// The count of drawn layers over a grid (render/cull/cover_layers.h): which
// boxes it calls covered for a square, a square over a larger one (a fold's
// inner edge), a hole and a face walked the other way, and, for scattered
// triangles, that every point of a box it calls covered lies in a face
// drawn the drawn way even after every corner moves by the slack.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "render/cull/cover_layers.h"

namespace toond::render {
namespace {

constexpr double kSlack = 1.0 / 64.0;

using Triangle = std::array<glm::dvec2, 3>;

double area2(const Triangle& t) {
  const glm::dvec2 ab = t[1] - t[0], ac = t[2] - t[0];
  return ab.x * ac.y - ab.y * ac.x;
}

// The chain's outline: every edge not walked back by another of the faces
// (its two ends bit for bit the same, the other way round).
std::vector<std::pair<glm::dvec2, glm::dvec2>> outline_of(const std::vector<Triangle>& faces) {
  std::map<std::array<double, 4>, int> walked;
  for (const Triangle& t : faces) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 a = t[k], b = t[(k + 1) % 3];
      ++walked[{a.x, a.y, b.x, b.y}];
    }
  }
  std::vector<std::pair<glm::dvec2, glm::dvec2>> out;
  for (const Triangle& t : faces) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 a = t[k], b = t[(k + 1) % 3];
      const auto back = walked.find({b.x, b.y, a.x, a.y});
      if (back == walked.end() || back->second == 0) out.emplace_back(a, b);
    }
  }
  return out;
}

CoverLayers layers_of(const std::vector<Triangle>& faces, int size, double cell, bool counter_clockwise = true) {
  CoverLayers layers;
  layers.reset({size, size, cell, glm::dvec2(0.0), glm::dvec2(size)}, counter_clockwise, kSlack);
  for (const auto& [a, b] : outline_of(faces)) layers.add_outline_edge(a, b);
  layers.finish();
  return layers;
}

// A square [lo, hi]², counter-clockwise (y up), as two triangles.
std::vector<Triangle> square(double lo, double hi) {
  return {{glm::dvec2(lo, lo), glm::dvec2(hi, lo), glm::dvec2(hi, hi)},
          {glm::dvec2(lo, lo), glm::dvec2(hi, hi), glm::dvec2(lo, hi)}};
}

bool covers(const CoverLayers& layers, double x0, double y0, double x1, double y1) {
  return layers.covers(glm::dvec2(x0, y0), glm::dvec2(x1, y1));
}

TEST(CoverLayers, ASquareCoversBoxesInsideItOnly) {
  const CoverLayers layers = layers_of(square(10.3, 40.7), 64, 1.0);
  EXPECT_TRUE(covers(layers, 12.0, 12.0, 38.5, 38.5));
  EXPECT_TRUE(covers(layers, 20.0, 20.0, 21.0, 21.0));
  EXPECT_FALSE(covers(layers, 8.0, 20.0, 12.0, 22.0)) << "across its left side";
  EXPECT_FALSE(covers(layers, 20.0, 39.0, 22.0, 42.0)) << "across its top";
  EXPECT_FALSE(covers(layers, 50.0, 50.0, 52.0, 52.0)) << "outside";
}

TEST(CoverLayers, ASquareWalkedClockwiseCoversWhereItsFacesAreDrawnThatWay) {
  std::vector<Triangle> mirrored;
  for (Triangle t : square(10.3, 40.7)) mirrored.push_back({t[0], t[2], t[1]});
  const CoverLayers layers = layers_of(mirrored, 64, 1.0, false);
  EXPECT_TRUE(covers(layers, 12.0, 12.0, 38.5, 38.5));
  EXPECT_FALSE(covers(layers, 8.0, 20.0, 12.0, 22.0));
  // Read as counter-clockwise faces, it is a face turned away: nothing.
  EXPECT_FALSE(covers(layers_of(mirrored, 64, 1.0, true), 20.0, 20.0, 21.0, 21.0));
}

// A small square drawn over a large one: its edge ends its own cover, but
// the large one lies under both sides of it (two layers inside, one
// outside), so a box across that edge is covered. (Not yet across its
// corners: a cell's centre inside the corner lies on the faces' side of
// both edges there, so it counts both as lowering, where a straight way
// out of the corner crosses one.)
TEST(CoverLayers, AnEdgeWithAnotherLayerUnderBothSidesIsCovered) {
  std::vector<Triangle> faces = square(4.2, 60.1);
  for (const Triangle& t : square(20.4, 35.6)) faces.push_back(t);
  const CoverLayers layers = layers_of(faces, 64, 1.0);
  EXPECT_TRUE(covers(layers, 18.0, 25.0, 23.0, 27.0)) << "across the small square's left side";
  EXPECT_TRUE(covers(layers, 25.0, 33.0, 27.0, 38.0)) << "across its top";
  EXPECT_FALSE(covers(layers, 2.0, 25.0, 6.0, 27.0)) << "across the large one's side";
}

TEST(CoverLayers, AHoleIsNotCovered) {
  // A frame: the square [4, 60] with the square [20, 36] left out, as the
  // four trapezoids' triangles between the two.
  const glm::dvec2 outer[4] = {{4, 4}, {60, 4}, {60, 60}, {4, 60}};
  const glm::dvec2 inner[4] = {{20, 20}, {36, 20}, {36, 36}, {20, 36}};
  std::vector<Triangle> faces;
  for (int k = 0; k < 4; ++k) {
    const int next = (k + 1) % 4;
    faces.push_back({outer[k], outer[next], inner[next]});
    faces.push_back({outer[k], inner[next], inner[k]});
  }
  const CoverLayers layers = layers_of(faces, 64, 1.0);
  EXPECT_TRUE(covers(layers, 8.0, 8.0, 16.0, 50.0));
  EXPECT_FALSE(covers(layers, 26.0, 26.0, 30.0, 30.0)) << "inside the hole";
  EXPECT_FALSE(covers(layers, 17.0, 26.0, 22.0, 28.0)) << "across the hole's rim";
}

// A face walked the other way round counts against the layers under it:
// a square whose right half is such a face over a drawn square leaves that
// half at no layer.
TEST(CoverLayers, AFaceWalkedTheOtherWayTakesALayerAway) {
  std::vector<Triangle> faces = square(4.2, 60.1);
  faces.push_back({glm::dvec2(30.5, 10.5), glm::dvec2(50.5, 50.5), glm::dvec2(50.5, 10.5)});
  const CoverLayers layers = layers_of(faces, 64, 1.0);
  EXPECT_FALSE(covers(layers, 45.0, 14.0, 48.0, 18.0));
  EXPECT_TRUE(covers(layers, 8.0, 40.0, 20.0, 55.0));
}

// The grid covers only the cells over the faces' box: a box's answer is
// the same as over the whole viewport's grid, and a box reaching past the
// grid is open.
TEST(CoverLayers, AGridOverTheFacesBoxAnswersAsTheWholeViewportsDoes) {
  std::vector<Triangle> faces = square(9.3, 57.8);
  for (const Triangle& t : square(20.4, 35.6)) faces.push_back(t);
  for (const double cell : {1.0, 2.0, 4.0}) {
    const CoverLayers whole = layers_of(faces, 96, cell);
    CoverLayers bounded;
    bounded.reset({96, 96, cell, glm::dvec2(9.3), glm::dvec2(57.8)}, true, kSlack);
    for (const auto& [a, b] : outline_of(faces)) bounded.add_outline_edge(a, b);
    bounded.finish();
    int covered = 0;
    for (double x = 2.0; x < 64.0; x += 1.7) {
      for (double y = 3.0; y < 64.0; y += 2.3) {
        const glm::dvec2 lo(x, y), hi(x + 3.1, y + 2.2);
        EXPECT_EQ(bounded.covers(lo, hi), whole.covers(lo, hi)) << cell << " at " << x << "," << y;
        covered += whole.covers(lo, hi);
      }
    }
    EXPECT_GT(covered, 100) << cell;
    EXPECT_FALSE(bounded.covers(glm::dvec2(50.0, 30.0), glm::dvec2(70.0, 32.0))) << "past the grid";
  }
}

// A cell more edges meet than the count of lowerings can hold is open,
// however many layers its centre reads: 300 thin squares over one point,
// each edge crossing the cell there.
TEST(CoverLayers, ACellMetByMoreEdgesThanItCountsIsOpen) {
  std::vector<Triangle> faces;
  for (int k = 0; k < 300; ++k) {
    const double shift = 1e-3 * k;  // apart by more than the slack's rounding, less than a cell
    for (const Triangle& t : square(10.2 + shift, 20.7 + shift)) faces.push_back(t);
  }
  CoverLayers layers;
  layers.reset({32, 32, 1.0, glm::dvec2(0.0), glm::dvec2(32.0)}, true, kSlack);
  for (const auto& [a, b] : outline_of(faces)) layers.add_outline_edge(a, b);
  layers.finish();
  EXPECT_TRUE(covers(layers, 14.0, 14.0, 16.0, 16.0)) << "well inside all of them";
  EXPECT_FALSE(covers(layers, 10.0, 14.0, 11.0, 15.0)) << "where all their left sides pass";
}

// Scattered small triangles, some drawn the other way, over a grid of
// cells of several sizes: every box called covered holds, at every point
// tried, a face drawn counter-clockwise, with every corner moved by up to
// the slack (the rasterizer's snapping).
TEST(CoverLayers, EveryPointOfACoveredBoxLiesInADrawnFaceAfterTheCornersMove) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> place(2.0, 46.0), size(-20.0, 20.0), unit(0.0, 1.0), nudge(-kSlack, kSlack);
  for (const double cell : {1.0, 2.0}) {
    std::vector<Triangle> faces;
    for (int i = 0; i < 120; ++i) {
      const glm::dvec2 at(place(random), place(random));
      Triangle t = {at, at + glm::dvec2(size(random), size(random)), at + glm::dvec2(size(random), size(random))};
      // Nine in ten drawn the drawn way.
      if ((area2(t) < 0.0) == (unit(random) < 0.9)) std::swap(t[1], t[2]);
      faces.push_back(t);
    }
    const CoverLayers layers = layers_of(faces, 48, cell);
    std::vector<Triangle> moved = faces;
    for (Triangle& t : moved) {
      for (glm::dvec2& corner : t) corner += glm::dvec2(nudge(random), nudge(random));
    }
    int covered_boxes = 0;
    for (int b = 0; b < 1000; ++b) {
      const glm::dvec2 lo(place(random), place(random));
      const glm::dvec2 hi = lo + glm::dvec2(2.0 * unit(random), 2.0 * unit(random));
      if (!layers.covers(lo, hi)) continue;
      ++covered_boxes;
      for (int p = 0; p < 64; ++p) {
        const glm::dvec2 point = lo + (hi - lo) * glm::dvec2(unit(random), unit(random));
        bool inside = false;
        for (const Triangle& t : moved) {
          if (area2(t) <= 0.0) continue;
          const bool in = area2({t[0], t[1], point}) >= 0.0 && area2({t[1], t[2], point}) >= 0.0 &&
                          area2({t[2], t[0], point}) >= 0.0;
          if (in) {
            inside = true;
            break;
          }
        }
        ASSERT_TRUE(inside) << "cell " << cell << ", box " << lo.x << "," << lo.y << " – " << hi.x << "," << hi.y;
      }
    }
    // Dense enough that most boxes are covered: the test tries many.
    EXPECT_GT(covered_boxes, 50) << cell;
  }
}

}  // namespace
}  // namespace toond::render
