#pragma once
// Runs of a level's triangles, in the order they are drawn, each with a
// bound on which way its faces turn: a draw that culls the faces turned
// away from the viewer can leave out a whole run whose faces surely all
// turn away, instead of having the vertex stage and the rasterizer's setup
// run for triangles the culling then drops.
//
// A face turns away from the eye when the eye lies behind its plane, and
// that holds for the whole plane: its distance from the eye's side is the
// same at every point of it. Each run keeps a ball round its corners and a
// cone round its faces' unit normals; if the direction from the eye to the
// ball's middle is within 90° − (the cone's half angle) of the cone's axis
// by enough to outweigh the ball's size, every face turns away. The test
// asks for a margin so faces nearly edge-on, which the rasterizer's
// snapping of corners may turn either way, keep their run drawn: the
// cosine of the turn must pass kMinimumTurn plus what moving the corners
// of the run's thinnest face by the slack could undo; a degenerate face
// keeps its run drawn. The order
// of what is drawn is kept: only runs are left out, so the image is the
// same byte for byte.
//
// Pure arithmetic, no GL; built once per level when the model is uploaded.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/face_culling.h"
#include "scene/mesh/model.h"

namespace toond::render {

// The viewer in the mesh's own coordinates (`forward` a unit vector): a
// face turns away in them where it does in the frame's, under a similarity
// (rotation, uniform scale, translation), mirrored or not.
struct MeshViewer : Viewer {
  // A drawn pixel's size in mesh units: at distance 1 from the eye
  // (perspective; it grows with the distance), or anywhere (orthographic).
  double pixel = 0;
};

// A range of the index buffer.
struct IndexRange {
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
};

class FacingRuns {
 public:
  // How many triangles a run holds (the last of a submesh may hold fewer):
  // runs of the vertex cache's order are only loosely together, and
  // shorter ones turn more uniformly (the bunny at 512² leaves out 12k of
  // its 52k triangles with 64, 19k with 16), while the leftover ranges,
  // merged, stay few enough to draw one by one.
  static constexpr std::size_t kRunTriangles = 16;
  // Faces turned away by less than this (the cosine of the angle between
  // the normal and the way to the eye, about 1.1°) keep their run drawn.
  static constexpr double kMinimumTurn = 0.02;
  // How far the rasterizer may put a corner from where it is (it snaps to
  // 1/256 px; vertex stage rounding is far less), as hull_cull.cpp's.
  static constexpr double kSlackPx = 1.0 / 64.0;

  FacingRuns() = default;
  // `indices` is the whole index buffer and `submeshes` index it.
  FacingRuns(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
             std::span<const scene::Submesh> submeshes);

  // The ranges of submesh `k` left once the runs whose faces all surely
  // turn away from `viewer` are taken out, neighbours merged, in order.
  void ranges_facing(std::size_t k, const MeshViewer& viewer, std::vector<IndexRange>& out) const;
  std::size_t run_count() const { return runs_.size(); }

 private:
  struct Run {
    IndexRange range;
    glm::dvec3 middle{0.0};  // of the ball round its corners
    double radius = 0;
    glm::dvec3 axis{0.0};  // unit; zero where no cone below 90° holds its normals
    double cos_half_angle = 0;
    double sin_half_angle = 1;
    double thinnest = 0;  // the least height of its faces (0: one is degenerate)
  };
  bool surely_turns_away(const Run& run, const MeshViewer& viewer) const;

  std::vector<Run> runs_;
  std::vector<std::size_t> first_run_;  // per submesh, then one past the last
};

// The frame's viewer (and a pixel's size in frame units at w = 1) seen
// from a mesh placed by `model` (mesh → frame coordinates); nullopt unless
// `model` is a similarity, under which alone the test carries over.
std::optional<MeshViewer> viewer_in_mesh(const glm::dmat4& model, const Viewer& frame_viewer,
                                         double world_per_px_at_w1);

}  // namespace toond::render
