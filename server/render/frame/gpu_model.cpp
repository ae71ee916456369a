#include "render/frame/gpu_model.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <span>

#include "gpu/gpu_error.h"
#include "render/frame/draw_pacing.h"
#include "render/frame/vertex_attribute.h"

namespace toond::render {
namespace {

struct Vertex {
  float position[3];
  float normal[3];
  float texcoord[2];
  float outline_normal[3];
  float tangent[4];  // xyz, w = bitangent handedness
  float color[3];    // sRGB-encoded vertex colour; white without one
};

void write_vertex(Vertex& v, const glm::vec3& position, const glm::vec3& normal, const glm::vec2& texcoord,
                  const glm::vec3& outline_normal, const glm::vec4& tangent, const glm::vec3& color) {
  std::memcpy(v.position, &position, sizeof v.position);
  std::memcpy(v.normal, &normal, sizeof v.normal);
  std::memcpy(v.texcoord, &texcoord, sizeof v.texcoord);
  std::memcpy(v.outline_normal, &outline_normal, sizeof v.outline_normal);
  std::memcpy(v.tangent, &tangent, sizeof v.tangent);
  std::memcpy(v.color, &color, sizeof v.color);
}

// A stream's value at vertex i, or `absent` where the mesh has none.
template <class T>
T at_or(std::span<const T> stream, std::size_t i, const T& absent) {
  return i < stream.size() ? stream[i] : absent;
}

const glm::vec2 kNoTexcoord(0.0f);
const glm::vec4 kNoTangent(1, 0, 0, 1);
const glm::vec3 kNoColor(1.0f);  // white

// The interleaved vertices of a mesh's streams; texcoords, tangents and
// colours may be empty (then (0,0), +X and white).
std::vector<Vertex> interleave(const scene::Mesh& mesh) {
  std::vector<Vertex> vertices(mesh.positions.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    write_vertex(vertices[i], mesh.positions[i], mesh.normals[i], at_or<glm::vec2>(mesh.texcoords, i, kNoTexcoord),
                 mesh.outline_normals[i], at_or<glm::vec4>(mesh.tangents, i, kNoTangent),
                 at_or<glm::vec3>(mesh.colors, i, kNoColor));
  }
  return vertices;
}

gpu::Texture upload_texture(const scene::Texture& tex, std::size_t& bytes) {
  gpu::Texture t = gpu::Texture::create(GL_TEXTURE_2D);
  const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(tex.width, tex.height))));
  // Colour maps decode from sRGB when sampled; normal maps hold vectors and
  // must come back exactly as stored.
  const GLenum format = tex.color_space == scene::ColorSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
  glTextureStorage2D(t.id(), levels, format, tex.width, tex.height);
  // Images are stored top row first; OBJ texture coordinates put v = 0 at
  // the bottom, which is GL's first row. Upload the rows reversed.
  const std::size_t row = static_cast<std::size_t>(tex.width) * 4;
  std::vector<std::uint8_t> flipped(tex.rgba.size());
  for (int y = 0; y < tex.height; ++y) {
    std::memcpy(flipped.data() + static_cast<std::size_t>(y) * row,
                tex.rgba.data() + static_cast<std::size_t>(tex.height - 1 - y) * row, row);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.id(), 0, 0, 0, tex.width, tex.height, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  bytes += tex.rgba.size() * 4 / 3;  // with the mip chain
  return t;
}

// Runs of crease edges, each edge standing for its two faces (face 1
// (a, b, c1), face 2 (b, a, c2)): a run whose faces all surely turn away
// holds only creases hidden behind the model's own faces. Six indices an
// edge, so a run of FacingRuns::kRunTriangles faces is a whole number of
// edges.
FacingRuns crease_runs(std::span<const glm::vec3> positions, const scene::CreaseEdges& creases) {
  static_assert(FacingRuns::kRunTriangles % 2 == 0);
  std::vector<std::uint32_t> faces;
  faces.reserve(creases.size() * 6);
  for (std::size_t e = 0; e < creases.size(); ++e) {
    const std::uint32_t* edge = &creases.indices[4 * e];  // c1, a, b, c2
    faces.insert(faces.end(), {edge[1], edge[2], edge[0], edge[2], edge[1], edge[3]});
  }
  const scene::Submesh all{0, static_cast<std::uint32_t>(faces.size()), 0};
  return FacingRuns(positions, faces, std::span<const scene::Submesh>(&all, 1));
}

// Every level's segments where the parts cross, full detail first: at rest,
// or in a pose.
std::vector<const scene::IntersectionLines*> seams_of(const scene::Mesh& mesh) {
  std::vector<const scene::IntersectionLines*> levels = {&mesh.intersections};
  for (const scene::MeshLod& lod : mesh.lods) levels.push_back(&lod.intersections);
  return levels;
}

std::vector<const scene::IntersectionLines*> seams_of(const scene::SkinPose& pose) {
  std::vector<const scene::IntersectionLines*> levels;
  for (const scene::IntersectionLines& lines : pose.intersections) levels.push_back(&lines);
  return levels;
}

}  // namespace

GpuModel::GpuModel(const scene::Model& model) {
  const scene::Mesh& mesh = model.mesh;
  const std::vector<Vertex> vertices = interleave(mesh);
  // Every level's indices in one buffer, full detail first; each level's
  // submesh ranges are moved to where its indices land.
  std::vector<std::uint32_t> indices = mesh.indices;
  levels_.push_back({mesh.submeshes, 0, mesh.indices.size()});
  for (const scene::MeshLod& lod : mesh.lods) {
    Level level{lod.submeshes, indices.size(), lod.indices.size()};
    for (scene::Submesh& sub : level.submeshes) sub.first_index += static_cast<std::uint32_t>(level.first_index);
    indices.insert(indices.end(), lod.indices.begin(), lod.indices.end());
    levels_.push_back(std::move(level));
  }
  auto add_caps = [&](Level& level, const std::vector<std::uint32_t>& cap_indices) {
    level.first_cap_index = indices.size();
    level.cap_index_count = cap_indices.size();
    indices.insert(indices.end(), cap_indices.begin(), cap_indices.end());
  };
  add_caps(levels_[0], mesh.cap_indices);
  for (std::size_t i = 0; i < mesh.lods.size(); ++i) add_caps(levels_[i + 1], mesh.lods[i].cap_indices);
  auto add_creases = [&](Level& level, const scene::CreaseEdges& creases) {
    level.first_crease_index = indices.size();
    level.creased_over = creases.edges_over;
    if (creases.size() > 0) level.crease_runs = crease_runs(mesh.positions, creases);
    indices.insert(indices.end(), creases.indices.begin(), creases.indices.end());
  };
  add_creases(levels_[0], mesh.crease_edges);
  for (std::size_t i = 0; i < mesh.lods.size(); ++i) add_creases(levels_[i + 1], mesh.lods[i].crease_edges);

  vertices_ = gpu::Buffer::create();
  glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(), 0);
  indices_ = gpu::Buffer::create();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                       0);
  gpu_bytes_ = vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t);
  seams_ = GpuSeams(seams_of(mesh));
  gpu_bytes_ += seams_.gpu_bytes();
  for (Level& level : levels_) level.facing_runs = FacingRuns(mesh.positions, indices, level.submeshes);
  rest_positions_ = std::make_shared<const std::vector<glm::vec3>>(mesh.positions);
  outline_offsets_ = std::make_shared<const std::vector<glm::vec3>>(mesh.outline_normals);
  all_indices_ = std::make_shared<const std::vector<std::uint32_t>>(std::move(indices));

  vao_ = gpu::VertexArray::create();
  glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  auto attribute = [&](GLuint location, GLint size, std::size_t offset) {
    glEnableVertexArrayAttrib(vao_.id(), location);
    glVertexArrayAttribFormat(vao_.id(), location, size, GL_FLOAT, GL_FALSE, static_cast<GLuint>(offset));
    glVertexArrayAttribBinding(vao_.id(), location, 0);
  };
  attribute(kPositionAttribute, 3, offsetof(Vertex, position));
  attribute(kNormalAttribute, 3, offsetof(Vertex, normal));
  attribute(kTexcoordAttribute, 2, offsetof(Vertex, texcoord));
  attribute(kOutlineOffsetAttribute, 3, offsetof(Vertex, outline_normal));
  attribute(kTangentAttribute, 4, offsetof(Vertex, tangent));
  attribute(kColorAttribute, 3, offsetof(Vertex, color));

  if (model.rig) {
    skin_ = std::make_unique<GpuSkin>(mesh, *model.rig);
    gpu_bytes_ += skin_->gpu_bytes();
  }
  for (const scene::Texture& tex : model.textures) textures_.push_back(upload_texture(tex, gpu_bytes_));
  for (const scene::Material& m : model.materials) {
    materials_.push_back({m.name, m.diffuse_texture, m.normal_texture, m.unlit});
    MaterialBlock block;
    block.base_color = m.diffuse;
    block.opacity = m.opacity;
    block.has_texture = m.diffuse_texture >= 0 ? 1 : 0;
    material_blocks_.push_back(material_arena_.add(block));
  }
  material_arena_.upload();
}

void GpuModel::bind() const {
  glBindVertexArray(vao_.id());
  if (skinned_) skin_->bind();
}

void GpuModel::apply_pose(std::shared_ptr<const scene::SkinPose> pose, const scene::Model& model) {
  if (pose && pose == applied_) return;
  applied_.reset();  // until the buffers hold the new pose
  const bool was_cpu_posed = posed_ && !skinned_;
  posed_ = pose != nullptr && skin_ != nullptr && model.rig != nullptr;
  skinned_ = posed_ && !pose->cpu_sums;
  const bool cpu_posed = posed_ && !skinned_;
  // A model never posed on the CPU costs no GL call here.
  if (was_cpu_posed && !cpu_posed) glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(Vertex));
  posed_seams_ = GpuSeams();
  if (!posed_) return;
  if (!pose->intersections.empty()) posed_seams_ = GpuSeams(seams_of(*pose));
  if (skinned_) skin_->upload(*pose);
  if (cpu_posed) pose_into_vertex_buffer(model, *pose->cpu_sums);
  applied_ = std::move(pose);
}

void GpuModel::pose_into_vertex_buffer(const scene::Model& model, const scene::PoseSums& sums) {
  const scene::Mesh& mesh = model.mesh;
  const std::size_t count = mesh.positions.size();
  if (!posed_vertices_) posed_vertices_ = gpu::Buffer::create();
  // Fresh storage each pose (the last one may still be drawn from), mapped
  // and written in place by the cores: no copy of the posed vertices is
  // made on the way, which on llvmpipe is most of what posing costs.
  const auto bytes = static_cast<GLsizeiptr>(count * sizeof(Vertex));
  glNamedBufferData(posed_vertices_.id(), bytes, nullptr, GL_STREAM_DRAW);
  auto* out = static_cast<Vertex*>(
      glMapNamedBufferRange(posed_vertices_.id(), 0, bytes, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
  if (out == nullptr) throw gpu::GpuError("cannot map the posed vertex buffer");
  const bool tangents = has_normal_maps();
  scene::for_each_vertex_run(count, [&](std::size_t first, std::size_t end) {
    for (std::size_t v = first; v < end; ++v) {
      const scene::PosedVertex posed = scene::pose_vertex(mesh, *model.rig, sums, v, tangents);
      write_vertex(out[v], posed.position, posed.normal, at_or<glm::vec2>(mesh.texcoords, v, kNoTexcoord),
                   posed.outline_normal, posed.tangent, at_or<glm::vec3>(mesh.colors, v, kNoColor));
    }
  });
  glUnmapNamedBuffer(posed_vertices_.id());
  glVertexArrayVertexBuffer(vao_.id(), 0, posed_vertices_.id(), 0, sizeof(Vertex));
}

GLuint GpuModel::image_texture(const std::shared_ptr<const scene::Texture>& image) const {
  constexpr std::size_t kKept = 8;
  const auto it = std::find_if(image_textures_.begin(), image_textures_.end(),
                               [&](const ImageTexture& kept) { return kept.image == image; });
  if (it != image_textures_.end()) {
    std::rotate(it, it + 1, image_textures_.end());
    return image_textures_.back().texture.id();
  }
  if (image_textures_.size() >= kKept) image_textures_.erase(image_textures_.begin());
  std::size_t bytes = 0;
  image_textures_.push_back({image, upload_texture(*image, bytes)});
  return image_textures_.back().texture.id();
}

void GpuModel::bind_material(int index) const {
  material_arena_.bind(MaterialBlock::kBinding, material_blocks_[static_cast<std::size_t>(index)],
                       sizeof(MaterialBlock));
}

void GpuModel::draw(const scene::Submesh& submesh, DrawPacing* pacing) const {
  draw_triangles(pacing, submesh.index_count, submesh.first_index);
}

std::size_t GpuModel::draw_facing(std::size_t lod, std::size_t k, const MeshViewer& viewer, DrawPacing* pacing) const {
  const Level& level = levels_[lod];
  const scene::Submesh& sub = level.submeshes[k];
  if (posed_) {
    draw(sub, pacing);
    return 0;
  }
  static thread_local std::vector<IndexRange> ranges;
  level.facing_runs.ranges_facing(k, viewer, ranges);
  std::size_t drawn = 0;
  for (const IndexRange& range : ranges) {
    draw_triangles(pacing, range.index_count, range.first_index);
    drawn += range.index_count;
  }
  return (sub.index_count - drawn) / 3;
}

std::size_t GpuModel::creased_edges(std::size_t lod, double degrees) const {
  const auto whole = static_cast<std::size_t>(std::clamp(std::floor(degrees), 0.0, 180.0));
  return levels_[lod].creased_over[whole];
}

std::size_t GpuModel::draw_creases(std::size_t lod, double degrees, const std::optional<MeshViewer>& viewer,
                                   DrawPacing* pacing) const {
  const Level& level = levels_[lod];
  const std::size_t creased = creased_edges(lod, degrees);
  if (creased == 0) return 0;
  if (!viewer || posed_) {
    draw_crease_edges(pacing, 4 * creased, level.first_crease_index);
    return creased;
  }
  // The runs' ranges count six indices an edge; the edges creased at this
  // angle are the first `creased`.
  static thread_local std::vector<IndexRange> ranges;
  level.crease_runs.ranges_facing(0, *viewer, ranges);
  std::size_t drawn = 0;
  for (const IndexRange& range : ranges) {
    const std::size_t first = range.first_index / 6;
    if (first >= creased) break;
    const std::size_t end = std::min<std::size_t>(creased, (range.first_index + range.index_count) / 6);
    draw_crease_edges(pacing, 4 * (end - first), level.first_crease_index + 4 * first);
    drawn += end - first;
  }
  return drawn;
}

std::size_t GpuModel::intersection_segments(std::size_t lod, double degrees) const {
  return (posed_ ? posed_seams_ : seams_).segments(lod, degrees);
}

std::size_t GpuModel::draw_intersections(std::size_t lod, double degrees, DrawPacing* pacing) const {
  return (posed_ ? posed_seams_ : seams_).draw(lod, degrees, pacing);
}

void GpuModel::draw_all(std::size_t lod, DrawPacing* pacing) const {
  const Level& level = levels_[lod];
  draw_triangles(pacing, level.index_count, level.first_index);
}

void GpuModel::draw_from(const gpu::Buffer& indices, std::size_t index_count, std::size_t first_index,
                         DrawPacing* pacing) const {
  glVertexArrayElementBuffer(vao_.id(), indices.id());
  draw_triangles(pacing, index_count, first_index);
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
}

std::shared_ptr<const HullCullMesh> GpuModel::hull_cull_mesh(std::size_t lod, BackgroundThread& builder) const {
  if (posed_) return nullptr;
  const Level& level = levels_[lod];
  {
    std::lock_guard lock(level.hull_cull->mutex);
    if (level.hull_cull->mesh || level.hull_cull->building) return level.hull_cull->mesh;
    level.hull_cull->building = true;
  }
  std::vector<scene::Submesh> submeshes = level.submeshes;
  for (scene::Submesh& sub : submeshes) sub.first_index -= static_cast<std::uint32_t>(level.first_index);
  builder.post([slot = level.hull_cull, positions = rest_positions_, offsets = outline_offsets_, indices = all_indices_,
                first = level.first_index, count = level.index_count, submeshes = std::move(submeshes)] {
    std::shared_ptr<const HullCullMesh> mesh;
    try {
      mesh = std::make_shared<const HullCullMesh>(
          positions, offsets, std::span<const std::uint32_t>(*indices).subspan(first, count), submeshes);
    } catch (const std::bad_alloc&) {
      return;  // left building: this level's hull is drawn whole
    }
    std::lock_guard lock(slot->mutex);
    slot->mesh = std::move(mesh);
  });
  return nullptr;
}

void GpuModel::draw_caps(std::size_t lod, DrawPacing* pacing) const {
  const Level& level = levels_[lod];
  if (level.cap_index_count == 0) return;
  draw_triangles(pacing, level.cap_index_count, level.first_cap_index);
}

}  // namespace toond::render
