#pragma once
// Which of the inverted hull's faces can draw nothing, worked out on the
// CPU before the hull is drawn.
//
// The hull draws only outside the stencil mark the main pass left, that is
// outside every sample the model's drawn faces cover. A hull face comes
// from one model face T, moved out by at most the outline's width. Take a
// box round T and its hull face. Where no edge at which the drawn faces'
// cover can end (an edge drawn on one side only: the silhouette, a hole's
// rim, a fold, a face too thin to say which way it turns, an edge three
// faces share) crosses that box, and the box holds a covered point (T
// itself when the main pass draws it, else the middle of a face it draws),
// the box is connected, holds a covered point and meets no end of the
// cover: all of it is covered, every sample the hull face could reach is
// marked, and leaving the face out changes no byte, whichever way T and
// its hull face turn. Everything is bounded with a margin well above float
// rounding and the rasterizer's snapping of vertices to its sub-pixel grid.
//
// Inside the model the cover ends at folds too (the rim of a nearer part
// over a farther one), where more drawn faces lie behind that edge. There
// a face is left out where every cell its box meets surely lies under at
// least one layer of drawn faces (render/cull/cover_layers.h: the winding
// number of the drawn faces' outline, less what the outline's edges
// through the cell could take away).
//
// Where the hull pass skips one side of the hull (a closed model's), the
// faces that may show but surely turn to that side are set apart too: the
// draw that culls that side leaves them out instead of shading their
// vertices for nothing, and the draw of the other side (where a hole's cap
// shows) takes them. A hull corner lies between half and the whole of its
// move (hull.vert's obliquity factor), so its face turns that side when it
// does for every choice of the three corners on their moves, by more than
// rounding can undo; the signed area is affine in each corner's place
// along its move, so the eight choices at the ends bound it.
//
// On a CPU rasterizer setting up and binning a triangle costs the recording
// thread more than this test does; on a GPU it does not pay (renderer.h).
// Pure arithmetic, no GL.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/face_culling.h"
#include "scene/mesh/model.h"

namespace toond::render {

// One level of detail of a mesh as the cull reads it: built once, on first
// use (the neighbours cost a sort of the level's edges).
class HullCullMesh {
 public:
  // `indices` and `submeshes` are the level's (submeshes index `indices`);
  // positions and outline offsets are the mesh's whole vertex streams,
  // shared so a cull still running on another thread keeps them.
  using Stream = std::shared_ptr<const std::vector<glm::vec3>>;
  HullCullMesh(Stream positions, Stream outline_offsets, std::span<const std::uint32_t> indices,
               std::span<const scene::Submesh> submeshes);

  std::span<const std::uint32_t> indices() const { return indices_; }
  std::span<const scene::Submesh> submeshes() const { return submeshes_; }
  // Across edge k of triangle t (corner k to corner k+1): the triangle
  // that shares it with the same two positions, walked the other way, or
  // -1 where there is none, or more than one, or it runs the same way.
  std::int32_t neighbour(std::size_t t, int k) const { return neighbours_[3 * t + static_cast<std::size_t>(k)]; }
  std::span<const std::uint32_t> used_vertices() const { return used_; }
  // One id per distinct position: vertices split at a seam share it.
  std::uint32_t welded(std::uint32_t v) const { return welded_[v]; }
  const glm::vec3& position(std::uint32_t v) const { return (*positions_)[v]; }
  const glm::vec3& outline_offset(std::uint32_t v) const { return (*offsets_)[v]; }
  double outline_offset_length(std::uint32_t v) const { return offset_lengths_[v]; }

 private:
  Stream positions_;
  Stream offsets_;
  std::vector<std::uint32_t> indices_;
  std::vector<scene::Submesh> submeshes_;
  std::vector<std::int32_t> neighbours_;
  std::vector<std::uint32_t> welded_;
  std::vector<std::uint32_t> used_;  // every vertex a triangle of the level uses, once
  std::vector<double> offset_lengths_;
};

// How the hull of one object is drawn in this frame: hull.vert's inputs.
struct HullCullView {
  glm::dmat4 model{1.0};          // model → frame coordinates
  glm::dmat3 normal_matrix{1.0};  // inverse-transpose of the model's 3×3
  glm::dmat4 clip{1.0};           // frame → clip coordinates
  double width_px = 0;            // the outline's width, drawn pixels
  double world_per_px_at_w1 = 0;
  int viewport_width = 0;
  int viewport_height = 0;
  // The winding (in window coordinates, y up) of the faces the main pass
  // draws: counter-clockwise where it skips back faces or none, clockwise
  // where it skips the front ones (a mirroring transform).
  bool drawn_clockwise = false;
  // The side of the hull the hull pass culls (where it draws that side
  // after all because a cap shows, it draws the faces set apart too).
  HiddenFaces hull_hidden = HiddenFaces::None;
  // Whether to count the layers at folds too (cover_layers.h). They cost
  // the cull a fifth to a third more; with one sample a pixel the faces
  // they leave out cost the rasterizer about that much, and where the cull
  // is on the frame's critical path (a main pass recorded fast, the
  // armadillo's) the frame gets slower (at MSAA 1: the armadillo 7.4 →
  // 8.2 ms with them, the bunny 12.3 → 11.3; at MSAA 4 both gain).
  bool count_layers = true;
};

// The hull's triangles that may draw something, submesh by submesh: first
// those that may turn to the side the hull pass draws, then those that
// surely turn to the side it culls.
struct HullSubset {
  std::vector<std::uint32_t> indices;
  std::vector<scene::Submesh> submeshes;    // ranges of `indices`, the level's materials in its order
  std::vector<scene::Submesh> turned_away;  // the same materials' faces set apart, after all of those
  std::size_t culled_triangles = 0;         // left out: they draw nothing either way

  // How many indices lead, before the faces set apart.
  std::size_t facing_index_count() const {
    return turned_away.empty() ? indices.size() : turned_away.front().first_index;
  }
  std::size_t turned_away_triangles() const { return (indices.size() - facing_index_count()) / 3; }
};

// One object's cull: its level's mesh and the frame's view of it.
struct HullCullInput {
  std::shared_ptr<const HullCullMesh> mesh;
  HullCullView view;
};

// nullopt where the test cannot be made (a vertex or its hull corner
// outside the near or far plane: the cover then ends along the plane's cut,
// not at an edge): the whole hull is drawn.
// Any thread; one call at a time per thread.
std::optional<HullSubset> hull_faces_that_may_show(const HullCullMesh& mesh, const HullCullView& view);

}  // namespace toond::render
