#pragma once
// A model's GPU copy: one interleaved vertex buffer, one index buffer (the
// full mesh, then each coarser level of detail, then every level's caps,
// then every level's crease edges), every level's segments where its
// parts cross, at rest and in the applied pose (gpu_seams.h),
// its textures (sRGB, mipmapped, repeating), per-material draw ranges, one
// uniform block per material and, for a rigged model, its skinning
// (render/frame/gpu_skin.h). It holds what the GPU draws, not how a frame sees
// the model: bounds, levels and caps are the imported model's and the
// pose's (frame_context.h). Every draw goes through the frame's pacing
// (draw_pacing.h; null: drawn at once).
// Created and destroyed on the render thread only.
#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "gpu/gl_object.h"
#include "gpu/uniform_arena.h"
#include "render/cull/background_thread.h"
#include "render/cull/facing_runs.h"
#include "render/cull/hull_cull.h"
#include "render/frame/draw_pacing.h"
#include "render/frame/gpu_seams.h"
#include "render/frame/gpu_skin.h"
#include "render/frame/uniform_blocks.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::render {

// What the passes choose variants and textures by; the colours a shader
// reads are in the material's uniform block (bind_material).
struct GpuMaterial {
  std::string name;         // as in the MTL, for per-material request parameters
  int texture = -1;         // index into GpuModel::textures()
  int normal_texture = -1;  // tangent-space normal map, linear
  bool unlit = false;
};

// Where a level's cull mesh lands once built off the render thread; shared
// with the build, which may outlive the model.
struct HullCullSlot {
  std::mutex mutex;
  std::shared_ptr<const HullCullMesh> mesh;  // guarded by mutex
  bool building = false;                     // guarded by mutex
};

class GpuModel {
 public:
  explicit GpuModel(const scene::Model& model);

  // Binds the vertex array and, when posed, the skinning blocks.
  void bind() const;
  // Draws the model in `pose` until the next call; nullptr: the rest pose.
  // A pose of joints and morph weights is uploaded as such and the vertex
  // stages move the rest vertices; a pose to pose on the CPU
  // (SkinPose::cpu_sums) is posed from `model` (the one this copy was made
  // from) by the cores straight into a vertex buffer of its own, with
  // indices and textures shared with the rest. Set before every render,
  // since the copy is cached between renders. A model without a rig takes
  // only nullptr. The pose last applied is kept: applying it again (the
  // frames of a sheet that share a time) costs nothing.
  void apply_pose(std::shared_ptr<const scene::SkinPose> pose, const scene::Model& model);
  // Whether the vertex stages pose it (ObjectBlock::skinned).
  bool skinned() const { return skinned_; }
  // Binds a material's uniform block (shaders/material.glsl), made once
  // when the model was uploaded.
  void bind_material(int index) const;
  // Draws one submesh (the VAO must be bound); the ranges of every level
  // index the one index buffer.
  void draw(const scene::Submesh& submesh, DrawPacing* pacing) const;
  // Submesh `k` of a level without its runs of faces that surely turn away
  // from `viewer` (render/cull/facing_runs.h); all of it while posed, since the
  // runs hold the rest pose. Returns how many triangles it left out.
  std::size_t draw_facing(std::size_t lod, std::size_t k, const MeshViewer& viewer, DrawPacing* pacing) const;
  // Every triangle of a level of detail (0 = full detail).
  void draw_all(std::size_t lod, DrawPacing* pacing) const;
  // The triangles closing a level's holes (scene::Mesh::cap_indices), with
  // the mesh's own vertices; nothing when it has none.
  void draw_caps(std::size_t lod, DrawPacing* pacing) const;
  // How many of a level's edges are creased at a crease angle of `degrees`
  // (scene/mesh/crease_edges.h).
  std::size_t creased_edges(std::size_t lod, double degrees) const;
  // Those edges as GL_LINES_ADJACENCY primitives (the crease pass's), with
  // `viewer` without the runs of them whose faces all surely turn away
  // from it (render/cull/facing_runs.h; all of them while posed, since the runs
  // hold the rest pose). Returns how many edges it drew.
  std::size_t draw_creases(std::size_t lod, double degrees, const std::optional<MeshViewer>& viewer,
                           DrawPacing* pacing) const;
  // How many of a level's segments where parts cross turn by more than
  // `degrees` (scene/mesh/intersection_lines.h): the rest pose's, or the
  // applied pose's (scene::SkinPose::intersections; none where it has
  // none).
  std::size_t intersection_segments(std::size_t lod, double degrees) const;
  // Those segments as GL_LINES_ADJACENCY primitives (the crease pass's,
  // p1, a, b, p2, posed already), from a vertex array of their own
  // (render/frame/gpu_seams.h), left bound. Returns how many it drew.
  std::size_t draw_intersections(std::size_t lod, double degrees, DrawPacing* pacing) const;
  // `index_count` indices from `first_index` of another element buffer (the
  // hull's faces that may show, render/cull/hull_cull.h), with this model's
  // vertices; its own indices are bound again after.
  void draw_from(const gpu::Buffer& indices, std::size_t index_count, std::size_t first_index,
                 DrawPacing* pacing) const;
  // A level's triangles as the hull cull reads them; null while posed (the
  // vertices the GPU draws are not the rest pose kept here). The first call
  // has them built on `builder`'s thread (pairing up the edges of a million
  // faces took 0.65 s, too long to hold a render for): null until then.
  std::shared_ptr<const HullCullMesh> hull_cull_mesh(std::size_t lod, BackgroundThread& builder) const;

  // The submeshes of a level of detail (0 = full detail; the rest come
  // from scene::Mesh::lods).
  const std::vector<scene::Submesh>& submeshes(std::size_t lod = 0) const { return levels_[lod].submeshes; }
  const std::vector<GpuMaterial>& materials() const { return materials_; }
  GLuint texture(int index) const { return textures_[static_cast<std::size_t>(index)].id(); }
  // A request's image for a material (`materials.<name>.texture`), uploaded
  // the first time it is drawn and kept while it is among the last few.
  GLuint image_texture(const std::shared_ptr<const scene::Texture>& image) const;
  bool has_normal_maps() const {
    for (const GpuMaterial& m : materials_)
      if (m.normal_texture >= 0) return true;
    return false;
  }
  std::size_t gpu_bytes() const { return gpu_bytes_; }

 private:
  gpu::VertexArray vao_;
  gpu::Buffer vertices_;
  std::unique_ptr<GpuSkin> skin_;  // a rigged model's
  bool posed_ = false;
  bool skinned_ = false;                            // posed by the vertex stages
  std::shared_ptr<const scene::SkinPose> applied_;  // what the buffers hold now
  gpu::Buffer posed_vertices_;                      // made by the first pose posed on the CPU
  gpu::Buffer indices_;
  std::vector<gpu::Texture> textures_;
  // Request images, most recently drawn last; each keeps its image alive so
  // its address stays its own.
  struct ImageTexture {
    std::shared_ptr<const scene::Texture> image;
    gpu::Texture texture;
  };
  mutable std::vector<ImageTexture> image_textures_;
  std::vector<GpuMaterial> materials_;
  gpu::UniformArena material_arena_;
  std::vector<std::size_t> material_blocks_;  // each material's offset in the arena
  struct Level {
    std::vector<scene::Submesh> submeshes;  // ranges of the shared index buffer
    std::size_t first_index = 0;            // the level's whole range
    std::size_t index_count = 0;
    std::size_t first_cap_index = 0;  // the caps' range of the index buffer
    std::size_t cap_index_count = 0;
    std::shared_ptr<HullCullSlot> hull_cull = std::make_shared<HullCullSlot>();
    FacingRuns facing_runs{};
    std::size_t first_crease_index = 0;             // the crease edges' range of the index buffer, four an edge
    std::array<std::uint32_t, 181> creased_over{};  // scene::CreaseEdges::edges_over
    // The crease edges' two faces each, as runs of FacingRuns::kRunTriangles
    // faces: half as many edges a run, in the edges' order.
    FacingRuns crease_runs{};
  };
  std::vector<Level> levels_;
  // The rest pose's positions and outline offsets and every level's
  // indices, kept on the CPU for the hull cull.
  HullCullMesh::Stream rest_positions_;
  HullCullMesh::Stream outline_offsets_;
  std::shared_ptr<const std::vector<std::uint32_t>> all_indices_;
  void pose_into_vertex_buffer(const scene::Model& model, const scene::PoseSums& sums);
  GpuSeams seams_;        // at rest
  GpuSeams posed_seams_;  // in the applied pose
  std::size_t gpu_bytes_ = 0;
};

}  // namespace toond::render
