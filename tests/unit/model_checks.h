#pragma once
// Checks shared by the importer tests (OBJ, .m, bundle dispatch).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "image/png_codec.h"
#include "scene/import/bundle_import.h"
#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_error.h"
#include "support/shared_models.h"

namespace toond::scene::test_checks {

using Files = std::vector<std::pair<std::string, std::string>>;

inline Bundle make_bundle(const Files& files) {
  Bundle bundle;
  for (const auto& [path, content] : files) bundle.add(path, content);
  return bundle;
}

// An OBJ's text imported as a one-file upload of it.
inline Model model_of_obj(const std::string& obj) { return import_bundle(make_bundle({{"m.obj", obj}})); }

// A model folder as an upload of it: every file but its notes (.txt, .md,
// LICENSE); of its OBJ files only `only_obj` when given.
inline Bundle bundle_from_folder(const std::filesystem::path& dir, const std::string& only_obj = {}) {
  Bundle bundle;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string rel = std::filesystem::relative(entry.path(), dir).generic_string();
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".txt" || ext == ".md" || rel == "LICENSE") continue;
    if (ext == ".obj" && !only_obj.empty() && rel != only_obj) continue;
    bundle.add(rel, toond::test::read_file(entry.path()));
  }
  return bundle;
}

inline std::string tiny_png(std::uint8_t r, std::uint8_t g, std::uint8_t b, int w = 4, int h = 2) {
  image::Image img;
  img.width = w;
  img.height = h;
  img.rgba.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
    img.rgba[i] = r;
    img.rgba[i + 1] = g;
    img.rgba[i + 2] = b;
    img.rgba[i + 3] = 255;
  }
  return image::encode_png(img);
}

// The farthest any point of `a` lies from its nearest point of `b`.
inline double farthest_from(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  double worst = 0;
  for (const glm::dvec3& p : a) {
    double nearest = 1e300;
    for (const glm::dvec3& q : b) nearest = std::min(nearest, glm::length(p - q));
    worst = std::max(worst, nearest);
  }
  return worst;
}

inline bool has_warning(const Model& model, const std::string& needle) {
  return std::any_of(model.warnings.begin(), model.warnings.end(),
                     [&](const std::string& w) { return w.find(needle) != std::string::npos; });
}

inline std::string warnings_of(const Model& model) {
  std::string all;
  for (const auto& w : model.warnings) all += w + "\n";
  return all;
}

// Checks every invariant the GPU upload relies on.
inline void expect_well_formed(const Model& m) {
  const Mesh& mesh = m.mesh;
  const std::size_t n = mesh.positions.size();
  ASSERT_GT(n, 0u);
  EXPECT_EQ(mesh.normals.size(), n);
  EXPECT_EQ(mesh.outline_normals.size(), n);
  EXPECT_EQ(mesh.texcoords.size(), n);
  ASSERT_EQ(mesh.tangents.size(), n);
  EXPECT_TRUE(mesh.colors.empty() || mesh.colors.size() == n);
  EXPECT_EQ(m.has_vertex_colors, !mesh.colors.empty());
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  ASSERT_FALSE(m.materials.empty());
  for (const auto i : mesh.indices) ASSERT_LT(i, n);
  for (std::size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(std::isfinite(mesh.positions[v][k]));
      ASSERT_TRUE(glm::all(glm::lessThanEqual(mesh.bounds.min, mesh.positions[v])));
      ASSERT_TRUE(glm::all(glm::lessThanEqual(mesh.positions[v], mesh.bounds.max)));
    }
    ASSERT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-4f) << "vertex " << v;
    // Outline offsets are at least unit length; mitred corners are longer,
    // up to the 3-unit cap.
    const float outline_length = glm::length(mesh.outline_normals[v]);
    ASSERT_GE(outline_length, 1.0f - 1e-4f) << "vertex " << v;
    ASSERT_LE(outline_length, 3.0f + 1e-4f) << "vertex " << v;
    ASSERT_TRUE(std::isfinite(mesh.texcoords[v].x) && std::isfinite(mesh.texcoords[v].y));
    const glm::vec4 t = mesh.tangents[v];
    ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << "vertex " << v;
    ASSERT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-4f) << "vertex " << v;
    ASSERT_NEAR(glm::dot(glm::vec3(t), mesh.normals[v]), 0.0f, 1e-4f) << "vertex " << v;
    ASSERT_TRUE(t.w == 1.0f || t.w == -1.0f) << "vertex " << v;
    if (!mesh.colors.empty()) {
      ASSERT_TRUE(glm::all(glm::greaterThanEqual(mesh.colors[v], glm::vec3(0.0f))) &&
                  glm::all(glm::lessThanEqual(mesh.colors[v], glm::vec3(1.0f))))
          << "vertex " << v;
    }
  }
  std::uint32_t covered = 0;
  for (const auto& sub : mesh.submeshes) {
    EXPECT_EQ(sub.first_index, covered);
    EXPECT_GT(sub.index_count, 0u);
    EXPECT_EQ(sub.index_count % 3, 0u);
    ASSERT_GE(sub.material, 0);
    ASSERT_LT(static_cast<std::size_t>(sub.material), m.materials.size());
    covered += sub.index_count;
  }
  EXPECT_EQ(covered, mesh.indices.size());
  for (const auto& mat : m.materials) {
    ASSERT_LT(mat.diffuse_texture, static_cast<int>(m.textures.size()));
    ASSERT_LT(mat.normal_texture, static_cast<int>(m.textures.size()));
    if (mat.diffuse_texture >= 0) {
      EXPECT_EQ(m.textures[static_cast<std::size_t>(mat.diffuse_texture)].color_space, ColorSpace::Srgb) << mat.name;
    }
    if (mat.normal_texture >= 0) {
      EXPECT_EQ(m.textures[static_cast<std::size_t>(mat.normal_texture)].color_space, ColorSpace::Linear) << mat.name;
    }
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(mat.specular, glm::vec3(0.0f))) &&
                glm::all(glm::lessThanEqual(mat.specular, glm::vec3(1.0f))));
    EXPECT_TRUE(mat.shininess >= 0.0f && mat.shininess <= 1000.0f) << mat.shininess;
  }
}

// `import` (an importer taking only the bundle) refuses `bundle` with an
// ImportError that names `file` and whose message holds `needle` and `needle2`.
template <class Import>
void expect_import_error(Import&& import, const Bundle& bundle, const std::string& file, const std::string& needle,
                         const std::string& needle2 = {}) {
  try {
    import(bundle);
    ADD_FAILURE() << "no ImportError";
  } catch (const ImportError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(needle2), std::string::npos) << e.what();
  }
}

}  // namespace toond::scene::test_checks
