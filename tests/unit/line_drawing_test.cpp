// The parts of a vector line drawing (render/vector/): the SVG's path
// data, strokes chained through shared points, the pen's order, what one
// triangle hides of a segment, a mesh's edges, and a whole drawing of a
// cube planned as the daemon plans it. The drawing's accuracy against
// analytic scenes is checked through the daemon (tests/integration/
// svg_output_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <random>

#include "model_checks.h"
#include "render/plan/frame_plan.h"
#include "render/vector/line_drawing.h"
#include "render/vector/mesh_edges.h"
#include "render/vector/occluder_grid.h"
#include "render/vector/pen_order.h"
#include "render/vector/segment_visibility.h"
#include "render/vector/stroke_chains.h"
#include "render/vector/svg_document.h"
#include "support/generated_models.h"
#include "support/in_process_render.h"
#include "support/svg_drawing.h"

namespace toond::render::vector {
namespace {

TEST(LineDrawingSvg, PathDataRoundsToTwoDecimalsAndDropsRepeatedPoints) {
  const Polyline open{{{1.004, 2.0}, {1.0, 2.001}, {3.5, -0.001}, {10.129, 7.0}}, false};
  EXPECT_EQ(path_data(open), "M1,2L3.5,0 10.13,7");
  const Polyline closed{{{0, 0}, {10, 0}, {10, 10}}, true};
  EXPECT_EQ(path_data(closed), "M0,0L10,0 10,10Z");
  const Polyline dot{{{5.001, 5.0}, {5.0, 5.002}}, false};
  EXPECT_EQ(path_data(dot), "") << "a stroke that rounds to one point is left out";
}

TEST(LineDrawingSvg, CameraJsonRoundTrips) {
  SvgDrawing drawing;
  drawing.width = 64;
  drawing.height = 32;
  drawing.view[3] = glm::dvec4(0.1, -2.0 / 3.0, -5, 1);
  const nlohmann::json camera = nlohmann::json::parse(camera_json(drawing));
  ASSERT_EQ(camera["view"].size(), 16u);
  ASSERT_EQ(camera["projection"].size(), 16u);
  EXPECT_EQ(camera["view"][13].get<double>(), -2.0 / 3.0);
  EXPECT_EQ(camera["width"], 64);
  EXPECT_EQ(camera["height"], 32);
}

StrokePiece piece(std::uint32_t a, std::uint32_t b, glm::dvec2 pa, glm::dvec2 pb) { return {a, b, pa, pb}; }

// A drawing of `paths` open strokes of `points` points each, in two
// colours, with a hidden layer.
SvgDrawing many_strokes(std::size_t paths, std::size_t points) {
  SvgDrawing drawing;
  drawing.width = drawing.height = 4096;
  drawing.colour = {10, 20, 30};
  auto& silhouettes = drawing.layers[static_cast<std::size_t>(LineKind::Silhouette)];
  silhouettes.push_back({drawing.colour, {}});
  silhouettes.push_back({{200, 100, 50}, {}});
  drawing.hidden.emplace();
  for (std::size_t i = 0; i < paths; ++i) {
    Polyline line;
    for (std::size_t k = 0; k < points; ++k) line.points.push_back({1000.123 + 7.0 * k + 0.01 * i, 2000.456 + 3.0 * i});
    (i % 3 == 2 ? *drawing.hidden : silhouettes[i % 2].strokes).push_back(line);
  }
  return drawing;
}

// Written in pieces, the text is the same as written whole, every piece
// but the last at least the piece size and at most one path more; a
// receiver that refuses stops the writing.
TEST(LineDrawingSvg, WrittenInPiecesIsTheSameText) {
  const SvgDrawing drawing = many_strokes(3000, 12);
  const std::string whole = write_svg(drawing);
  std::vector<std::string> pieces;
  const bool finished = write_svg(
      drawing,
      [&](std::string_view piece) {
        pieces.emplace_back(piece);
        return true;
      },
      16384);
  EXPECT_TRUE(finished);
  std::string joined;
  for (const std::string& piece : pieces) joined += piece;
  EXPECT_EQ(joined, whole);
  ASSERT_GT(pieces.size(), 10u);
  for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
    EXPECT_GE(pieces[i].size(), 16384u) << "piece " << i;
    EXPECT_LT(pieces[i].size(), 16384u + 1024u) << "piece " << i;
  }
  std::size_t taken = 0;
  const bool stopped = !write_svg(
      drawing,
      [&](std::string_view) {
        ++taken;
        return taken < 3;
      },
      16384);
  EXPECT_TRUE(stopped);
  EXPECT_EQ(taken, 3u) << "pieces asked for after the receiver refused";
}

// The estimate that decides whether a drawing is streamed: never under
// the text's size, and not far over it.
TEST(LineDrawingSvg, EstimatedSizeBoundsTheText) {
  for (const auto& [paths, points] : {std::pair<std::size_t, std::size_t>{0, 0}, {10, 2}, {3000, 12}, {200, 400}}) {
    const SvgDrawing drawing = many_strokes(paths, points);
    const std::size_t written = write_svg(drawing).size(), estimated = estimated_svg_bytes(drawing);
    EXPECT_GE(estimated, written) << paths << " paths of " << points;
    EXPECT_LE(estimated, 2 * written + 2048) << paths << " paths of " << points;
  }
}

TEST(LineDrawingChains, ALoopIsOneClosedStroke) {
  const std::vector<StrokePiece> square = {piece(2, 3, {1, 1}, {0, 1}), piece(0, 1, {0, 0}, {1, 0}),
                                           piece(3, 0, {0, 1}, {0, 0}), piece(1, 2, {1, 0}, {1, 1})};
  const std::vector<Polyline> strokes = chain_strokes(square, 4);
  ASSERT_EQ(strokes.size(), 1u);
  EXPECT_TRUE(strokes[0].closed);
  EXPECT_EQ(strokes[0].points.size(), 4u);
}

TEST(LineDrawingChains, AJunctionGoesOnStraightAndDrawsEachPieceOnce) {
  // A "T": 0-1-2 straight along x, 1-3 up from the middle.
  const std::vector<StrokePiece> tee = {piece(0, 1, {0, 0}, {1, 0}), piece(1, 3, {1, 0}, {1, 1}),
                                        piece(1, 2, {1, 0}, {2, 0})};
  const std::vector<Polyline> strokes = chain_strokes(tee, 4);
  ASSERT_EQ(strokes.size(), 2u);
  std::size_t segments = 0;
  bool straight = false;
  for (const Polyline& s : strokes) {
    segments += s.points.size() - 1;
    straight |= s.points.size() == 3 && s.points[0].y == 0 && s.points[1].y == 0 && s.points[2].y == 0;
  }
  EXPECT_EQ(segments, 3u);
  EXPECT_TRUE(straight) << "the stroke through the junction goes on along x";
}

TEST(LineDrawingChains, CutEndsJoinNothing) {
  // Two pieces of one edge, cut apart where something hid the middle: their
  // cut ends have ids of their own.
  const std::vector<StrokePiece> cut = {piece(0, 2, {0, 0}, {1, 0}), piece(3, 1, {2, 0}, {3, 0})};
  EXPECT_EQ(chain_strokes(cut, 4).size(), 2u);
}

TEST(LineDrawingChains, StitchesEndsWithinTheGapAndNoOthers) {
  // Two halves of a line cut 0.4 px apart where another passed in front,
  // one of them drawn backwards, and a stroke 3 px off.
  const std::vector<Polyline> strokes = {
      {{{0, 0}, {10, 0}}, false}, {{{20, 0}, {10.4, 0}}, false}, {{{23, 0}, {30, 0}}, false}};
  const std::vector<Polyline> stitched = stitch_strokes(strokes, 1.0);
  ASSERT_EQ(stitched.size(), 2u);
  EXPECT_EQ(stitched[0].points.size(), 4u);
  EXPECT_EQ(stitched[1].points.size(), 2u);
  // A loop cut once closes.
  const std::vector<Polyline> loop = {{{{0.5, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0.3}}, false}};
  const std::vector<Polyline> closed = stitch_strokes(loop, 1.0);
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_TRUE(closed[0].closed);
}

TEST(LineDrawingPenOrder, ShortensTravelAndKeepsEveryStroke) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> at(0, 500);
  std::vector<Polyline> strokes;
  for (int i = 0; i < 400; ++i) {
    const glm::dvec2 a(at(random), at(random));
    strokes.push_back({{a, a + glm::dvec2(3, 1)}, i % 10 == 0});
  }
  const double before = pen_up_travel(strokes);
  std::vector<Polyline> ordered = strokes;
  order_for_pen(ordered);
  ASSERT_EQ(ordered.size(), strokes.size());
  EXPECT_LT(pen_up_travel(ordered), 0.25 * before);
  // The same strokes, some turned end for end.
  const auto key = [](const Polyline& p) {
    const auto [lo, hi] = std::minmax(
        {std::pair(p.points.front().x, p.points.front().y), std::pair(p.points.back().x, p.points.back().y)});
    return std::pair(lo, hi);
  };
  std::vector<std::pair<std::pair<double, double>, std::pair<double, double>>> a, b;
  for (const Polyline& p : strokes) a.push_back(key(p));
  for (const Polyline& p : ordered) b.push_back(key(p));
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
}

TEST(LineDrawingVisibility, ATriangleHidesTheStretchBehindIt) {
  // A segment along x at depth 10 behind a triangle at depth 5 that spans
  // x in [-4/3, 4/3] at y = 0: orthographic, that stretch is hidden; seen
  // from the origin, twice as far the triangle covers twice as wide.
  const glm::dvec3 a(-4, 0, -10), b(4, 0, -10);
  for (bool ortho : {false, true}) {
    Occluder o;
    ASSERT_TRUE(make_occluder({-2, -1, -5}, {2, -1, -5}, {0, 2, -5}, ortho, o));
    const auto [t0, t1] = hidden_interval(o, a, b - a, 0, 1, 1e-9);
    const glm::dvec3 p0 = a + t0 * (b - a), p1 = a + t1 * (b - a);
    EXPECT_NEAR(p0.x, ortho ? -4.0 / 3.0 : -8.0 / 3.0, 1e-6) << (ortho ? "orthographic" : "perspective");
    EXPECT_NEAR(p1.x, ortho ? 4.0 / 3.0 : 8.0 / 3.0, 1e-6) << (ortho ? "orthographic" : "perspective");
    // The same triangle behind the segment hides nothing.
    Occluder behind;
    ASSERT_TRUE(make_occluder({-2, -1, -20}, {2, -1, -20}, {0, 2, -20}, ortho, behind));
    const auto none = hidden_interval(behind, a, b - a, 0, 1, 1e-9);
    EXPECT_GE(none.first, none.second);
  }
}

// Two triangles of a square, side by side, and a segment behind them that
// crosses their shared side at a grazing angle: widened there, they hide
// all of it between them; narrowed (as a rim is), a sliver slips through.
TEST(LineDrawingVisibility, NeighboursSharingASideLeaveNoGap) {
  const glm::dvec3 a(-0.5, -0.5 - 2e-6, -10), b(0.5, 0.5 + 2e-6, -10);
  const double tolerance = 1e-6;
  for (bool shared : {true, false}) {
    Occluder lower, upper;
    ASSERT_TRUE(make_occluder({-1, -1, -5}, {1, -1, -5}, {1, 1, -5}, true, lower));
    ASSERT_TRUE(make_occluder({-1, -1, -5}, {1, 1, -5}, {-1, 1, -5}, true, upper));
    // The diagonal is lower's side 2 (corner 2 to 0) and upper's side 0.
    lower.shared_sides = shared ? 4 : 0;
    upper.shared_sides = shared ? 1 : 0;
    const auto h1 = hidden_interval(lower, a, b - a, 0, 1, tolerance);
    const auto h2 = hidden_interval(upper, a, b - a, 0, 1, tolerance);
    const auto [first, second] = std::minmax(h1, h2);
    EXPECT_EQ(first.first, 0.0);
    EXPECT_EQ(second.second, 1.0);
    if (shared) {
      EXPECT_GE(first.second, second.first) << "no gap between them";
    } else {
      EXPECT_LT(first.second, second.first) << "narrowed, they leave a gap";
    }
  }
}

TEST(LineDrawingVisibility, ClipsToTheViewAndItsMargin) {
  const ScreenMap screen = ScreenMap::of(glm::dmat4(1.0), 100, 100);  // clip space is view space
  const auto [lo, hi] = clip_to_view({-3, 0, 0}, {3, 0, 0}, screen, 0);
  EXPECT_NEAR(lo, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(hi, 2.0 / 3.0, 1e-12);
  const auto [wlo, whi] = clip_to_view({-3, 0, 0}, {3, 0, 0}, screen, 50);  // half the image more each side
  EXPECT_NEAR(wlo, 1.0 / 3.0 - 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(whi, 2.0 / 3.0 + 1.0 / 6.0, 1e-12);
}

TEST(LineDrawingEdges, FindsOpenAndSharedEdges) {
  const scene::Model disk = scene::test_checks::model_of_obj(test::disk_obj(12));
  const ModelEdges disk_edges = model_edges(disk, 0);
  std::size_t open = 0;
  for (const MeshEdge& e : disk_edges.edges) open += e.face1 == kNoFace;
  EXPECT_EQ(open, 12u);
  EXPECT_EQ(disk_edges.edges.size(), 24u);
  // The cube's corners are split per face (one normal a face): welded, its
  // 12 sides and 6 diagonals are all shared.
  const scene::Model cube = scene::test_checks::model_of_obj(test::cube_obj());
  const ModelEdges cube_edges = model_edges(cube, 0);
  EXPECT_EQ(cube_edges.group_count, 8u);
  EXPECT_EQ(cube_edges.edges.size(), 18u);
  for (const MeshEdge& e : cube_edges.edges) EXPECT_NE(e.face1, kNoFace);
}

// A model drawn as the daemon plans output svg.
test::SvgFile draw(std::shared_ptr<const scene::Model> model, nlohmann::json request, LineStats* stats = nullptr) {
  RenderParams params = test::complete_params(request);
  params.output = Output::Svg;
  params.lod_auto = false;  // as the pipeline draws it (svg_render.cpp)
  const std::vector<PlannedObject> planned{{*model, glm::dmat4(1.0), nullptr}};
  const FramePlan plan = plan_frame(params, planned);
  EdgeCache edges;
  const std::vector<std::shared_ptr<const scene::Model>> models{model};
  const LineDrawing drawing = draw_lines(plan, planned, models, edges);
  if (stats) *stats = drawing.stats;
  return test::read_svg_drawing(write_svg(drawing.svg));
}

TEST(LineDrawing, ACubesNineVisibleEdgesInTwoLayers) {
  const auto cube = std::make_shared<const scene::Model>(scene::test_checks::model_of_obj(test::cube_obj()));
  for (const char* projection : {"perspective", "orthographic"}) {
    const test::SvgFile svg = draw(cube, {{"camera", {{"yaw", 30}, {"pitch", 25}, {"projection", projection}}}});
    ASSERT_EQ(svg.layers.count("silhouette"), 1u);
    ASSERT_EQ(svg.layers.count("creases"), 1u);
    const auto& outline = svg.layers.at("silhouette").strokes;
    ASSERT_EQ(outline.size(), 1u) << projection;
    EXPECT_TRUE(outline[0].closed);
    EXPECT_EQ(outline[0].points.size(), 6u) << projection;
    std::size_t inner_segments = 0;
    for (const test::SvgStroke& s : svg.layers.at("creases").strokes) inner_segments += s.points.size() - 1;
    EXPECT_EQ(inner_segments, 3u) << projection;
    EXPECT_LE(svg.path_data.size(), 6u);
    EXPECT_EQ(svg.layers.at("creases").attributes.at("inkscape:groupmode"), "layer");
  }
}

// outline.color_mode texture reads the texture along each silhouette, as
// hull.frag does: (1 − texel × colour) × (1 − darken). A file's NaN
// texture coordinates read the first texel, not past the image.
TEST(LineDrawing, TextureModeColoursTheOutlineByTheTexelAndSurvivesNaNCoordinates) {
  scene::Model model = scene::test_checks::model_of_obj(test::cube_obj());
  scene::Texture texture;
  texture.width = texture.height = 1;
  texture.rgba = {255, 0, 0, 255};  // sRGB red
  model.textures.push_back(texture);
  for (scene::Material& m : model.materials) {
    m.diffuse = glm::vec3(1.0f);
    m.diffuse_texture = 0;
  }
  for (glm::vec2& uv : model.mesh.texcoords) uv = glm::vec2(std::numeric_limits<float>::quiet_NaN());
  const auto shared = std::make_shared<const scene::Model>(std::move(model));
  const test::SvgFile svg = draw(
      shared, {{"camera", {{"yaw", 30}, {"pitch", 25}}}, {"outline", {{"color_mode", "texture"}, {"darken", 0.5}}}});
  const auto& outline = svg.layers.at("silhouette").strokes;
  ASSERT_FALSE(outline.empty());
  // (1 − (1, 0, 0)) × 0.5 = (0, 0.5, 0.5) linear: #00bcbc in sRGB.
  for (const test::SvgStroke& s : outline) EXPECT_EQ(s.colour, "#00bcbc");
}

}  // namespace
}  // namespace toond::render::vector
