#include "render/vector/line_colours.h"

#include <algorithm>
#include <cmath>

#include "image/srgb.h"

namespace toond::render::vector {
namespace {

// Samples of the texture along an edge, averaged into its colour.
constexpr int kTextureSamples = 8;

Srgb srgb_of(const glm::vec3& linear) {
  return {image::linear_to_srgb_byte(linear.r), image::linear_to_srgb_byte(linear.g),
          image::linear_to_srgb_byte(linear.b)};
}

const std::vector<scene::Submesh>& level_submeshes(const scene::Mesh& mesh, std::size_t level) {
  return level == 0 ? mesh.submeshes : mesh.lods[level - 1].submeshes;
}

// A texture coordinate in 0..1 as `wrap` folds it; a file's NaN or
// infinity reads the first texel rather than a cast past any int.
double wrapped(double t, scene::TextureWrap wrap) {
  if (!std::isfinite(t)) return 0.0;
  switch (wrap) {
    case scene::TextureWrap::ClampToEdge:
      return std::clamp(t, 0.0, 1.0);
    case scene::TextureWrap::MirroredRepeat: {
      const double period = t - 2.0 * std::floor(0.5 * t);
      return period > 1.0 ? 2.0 - period : period;
    }
    case scene::TextureWrap::Repeat:
      break;
  }
  return t - std::floor(t);
}

// The texel under `uv` (v = 0 at the bottom, as the image's last row), linear.
glm::vec3 texel_at(const scene::Texture& texture, glm::dvec2 uv, const DrawnMaterial& drawn) {
  const double u = wrapped(uv.x, drawn.wrap_s), v = wrapped(uv.y, drawn.wrap_t);
  const int x = std::clamp(static_cast<int>(u * texture.width), 0, texture.width - 1);
  const int y = std::clamp(static_cast<int>((1.0 - v) * texture.height), 0, texture.height - 1);
  const std::uint8_t* rgba = &texture.rgba[4 * (static_cast<std::size_t>(y) * texture.width + x)];
  glm::vec3 out;
  for (int c = 0; c < 3; ++c) {
    out[c] = texture.color_space == scene::ColorSpace::Srgb ? image::srgb_to_linear_table()[rgba[c]]
                                                            : static_cast<float>(rgba[c]) / 255.0f;
  }
  return out;
}

const scene::Texture* texture_of(const scene::Model& model, const DrawnMaterial& drawn) {
  const scene::Texture* texture = drawn.image.get();
  if (texture == nullptr && drawn.texture >= 0 && static_cast<std::size_t>(drawn.texture) < model.textures.size()) {
    texture = &model.textures[static_cast<std::size_t>(drawn.texture)];
  }
  const bool readable = texture != nullptr && texture->width > 0 && texture->height > 0 &&
                        texture->rgba.size() >= 4 * static_cast<std::size_t>(texture->width) * texture->height;
  return readable ? texture : nullptr;
}

}  // namespace

Srgb fixed_line_colour(const FramePlan& plan) {
  const RenderParams& p = plan.params;
  return srgb_of(plan.outline_px > 0 ? p.outline.color : p.contour.color);
}

LineColours::LineColours(const FramePlan& plan, const ViewMesh& mesh)
    : plan_(plan), mesh_(mesh), fixed_(fixed_line_colour(plan)), keep_(1.0f - plan.params.outline.darken) {
  const bool hull_lines = plan.passes.has(Pass::HullOutline) || plan.passes.has(Pass::Wireframe);
  if (hull_lines && plan.passes.outline.has(OutlineFeature::Texture)) {
    source_ = Source::Texture;
  } else if (hull_lines && plan.passes.outline.has(OutlineFeature::Material)) {
    source_ = Source::Material;
  }
  if (source_ == Source::Fixed) return;
  for (const ViewObject& object : mesh.objects) {
    std::vector<MaterialRun>& runs = runs_.emplace_back();
    for (const scene::Submesh& sub : level_submeshes(object.model->mesh, object.level)) {
      if (sub.index_count > 0) runs.push_back({sub.first_index / 3, sub.material});
    }
    std::sort(runs.begin(), runs.end(), [](const MaterialRun& a, const MaterialRun& b) { return a.first < b.first; });
  }
}

Srgb LineColours::of(const Segment& segment) const {
  const bool surface_line = segment.kind == LineKind::Silhouette || segment.kind == LineKind::Boundary;
  if (source_ == Source::Fixed || !surface_line || segment.face == kNoTriangle) return fixed_;
  return surface_colour(segment);
}

std::size_t LineColours::object_of(std::uint32_t triangle) const {
  const auto after = std::upper_bound(mesh_.objects.begin(), mesh_.objects.end(), triangle,
                                      [](std::uint32_t t, const ViewObject& o) { return t < o.first_triangle; });
  return static_cast<std::size_t>(after - mesh_.objects.begin()) - 1;
}

int LineColours::material_of(std::size_t object, std::uint32_t triangle) const {
  const std::vector<MaterialRun>& runs = runs_[object];
  const auto after = std::upper_bound(runs.begin(), runs.end(), triangle,
                                      [](std::uint32_t t, const MaterialRun& r) { return t < r.first; });
  return after == runs.begin() ? -1 : std::prev(after)->material;
}

// The texture along the edge in the face beside it (its corners at the
// edge's two positions), averaged in linear light.
glm::vec3 LineColours::texture_colour(std::size_t object, const DrawnMaterial& drawn, std::uint32_t triangle,
                                      const Segment& segment) const {
  const ViewObject& view = mesh_.objects[object];
  const scene::Texture* texture = texture_of(*view.model, drawn);
  const std::vector<glm::vec2>& texcoords = view.model->mesh.texcoords;
  glm::dvec2 uv_a{0.0}, uv_b{0.0};
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t point = mesh_.corners[3 * triangle + k];
    const std::uint32_t vertex = point - view.first_vertex;
    if (vertex >= texcoords.size()) continue;
    if (mesh_.groups[point] == segment.group_a) uv_a = glm::dvec2(texcoords[vertex]);
    if (mesh_.groups[point] == segment.group_b) uv_b = glm::dvec2(texcoords[vertex]);
  }
  glm::vec3 sum{0.0f};
  for (int i = 0; i < kTextureSamples; ++i) {
    const double t = (i + 0.5) / kTextureSamples;
    sum += texel_at(*texture, uv_a + t * (uv_b - uv_a), drawn);
  }
  return sum / static_cast<float>(kTextureSamples);
}

Srgb LineColours::surface_colour(const Segment& segment) const {
  const std::size_t object = object_of(segment.face);
  const ViewObject& view = mesh_.objects[object];
  const std::uint32_t local = segment.face - view.first_triangle;
  const int material = material_of(object, local);
  const std::vector<DrawnMaterial>& drawn = plan_.objects[object].materials;
  if (material < 0 || static_cast<std::size_t>(material) >= view.model->materials.size() ||
      static_cast<std::size_t>(material) >= drawn.size()) {
    return fixed_;
  }
  const glm::vec3 base = view.model->materials[static_cast<std::size_t>(material)].diffuse;
  const DrawnMaterial& look = drawn[static_cast<std::size_t>(material)];
  // As hull.frag: the texture (times the colour) inverted, or without a
  // texture the colour itself, darkened.
  if (source_ == Source::Texture && texture_of(*view.model, look) != nullptr) {
    return srgb_of((glm::vec3(1.0f) - texture_colour(object, look, segment.face, segment) * base) * keep_);
  }
  return srgb_of(base * keep_);
}

}  // namespace toond::render::vector
