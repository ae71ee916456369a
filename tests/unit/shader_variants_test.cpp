// Every program variant the plan can draw with compiles and links in
// glslang, the reference GLSL front end (a driver may accept what another
// rejects). The variants come from the same key types the plan builds
// (render/plan/shader_variant.h): all of them for the outline, depth and edge
// programs; for toon.frag, whose choices multiply to hundreds of
// thousands, a cover holding every pair of choices (support/variant_cover.h).
// Stage files are expanded with the renderer's own #include expansion.
#include <gtest/gtest.h>

#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "gpu/shader_includes.h"
#include "support/variant_cover.h"

namespace toond::render {
namespace {

struct Compiled {
  int status = -1;
  std::string log;
};

std::string source_file(const std::string& name) {
  std::ifstream in(std::filesystem::path(TOOND_SHADER_SOURCE_DIR) / name, std::ios::binary);
  if (!in) throw std::runtime_error("no shader file " + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class GlslangCheck {
 public:
  GlslangCheck() : dir_(std::filesystem::temp_directory_path() / ("toond-glslang-" + std::to_string(getpid()))) {
    std::filesystem::create_directories(dir_);
  }
  ~GlslangCheck() { std::filesystem::remove_all(dir_); }

  // Expands each stage's includes, then compiles and links the stages with
  // the defines.
  Compiled compile(const std::vector<std::string>& stages, const std::vector<std::string>& defines) const {
    std::string command = std::string(TOOND_GLSLANG_VALIDATOR) + " -l";
    for (std::string define : defines) {
      // "LIGHT_COUNT 2" is -DLIGHT_COUNT=2 on the command line.
      if (const auto space = define.find(' '); space != std::string::npos) define[space] = '=';
      command += " -D" + define;
    }
    for (const std::string& stage : stages) {
      std::ofstream(dir_ / stage, std::ios::binary) << gpu::expand_includes(stage, source_file).text;
      command += " " + (dir_ / stage).string();
    }
    command += " 2>&1";
    Compiled out;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) return out;
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), chunk.size(), pipe.get())) out.log += chunk.data();
    out.status = pclose(pipe.release());
    return out;
  }

  template <class Variant>
  void expect_all_compile(const std::vector<std::string>& stages, const std::vector<Variant>& variants) const {
    for (const Variant& variant : variants) {
      const std::vector<std::string> defines = variant.defines();
      const Compiled result = compile(stages, defines);
      std::string named;
      for (const std::string& s : stages) named += s + " ";
      for (const std::string& d : defines) named += "-D" + d + " ";
      EXPECT_EQ(result.status, 0) << named << "\n" << result.log;
    }
  }

 private:
  std::filesystem::path dir_;
};

// One clear failure, not one per variant, where the compiler is missing.
class ShaderVariants : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(std::filesystem::exists(TOOND_GLSLANG_VALIDATOR))
        << TOOND_GLSLANG_VALIDATOR << " is missing: these tests compile every shader variant offline with it "
        << "(Debian's glslang-tools, which scripts/install-deps.sh installs)";
  }
};

TEST_F(ShaderVariants, APairwiseCoverOfTheShadingFeaturesCompilesInGlslang) {
  const std::vector<ToonVariant> variants = test::pairwise_toon_variants();
  std::printf("[variants] %zu toon.frag variants cover every pair of feature choices\n", variants.size());
  ASSERT_GE(variants.size(), 24u) << "the cover is at least the two largest dimensions' product (8 × 3)";
  GlslangCheck().expect_all_compile({"toon.vert", "toon.frag"}, variants);
}

TEST_F(ShaderVariants, EveryOutlineVariantCompilesForTheHullAndTheWireframe) {
  std::vector<FeatureSet<OutlineFeature>> hull, wire;
  for (const auto& variant : FeatureSet<OutlineFeature>::all()) {
    (variant.has(OutlineFeature::LineSegment) ? wire : hull).push_back(variant);
  }
  ASSERT_EQ(hull.size(), 8u);
  const GlslangCheck glslang;
  glslang.expect_all_compile({"hull.vert", "hull.frag"}, hull);
  glslang.expect_all_compile({"wire.vert", "wire.geom", "hull.frag"}, wire);
}

TEST_F(ShaderVariants, EveryDepthEdgeCreaseDownsampleAndLayerVariantCompiles) {
  const GlslangCheck glslang;
  glslang.expect_all_compile({"shadow.vert", "shadow.frag"}, DepthVariant::all());
  glslang.expect_all_compile({"toon.vert", "normal_depth.frag"}, DepthVariant::all());
  glslang.expect_all_compile({"fullscreen.vert", "edges.frag"}, EdgeVariant::all());
  glslang.expect_all_compile({"fullscreen.vert", "normal_depth_resolve.frag"}, std::vector<EdgeVariant>{{}});
  glslang.expect_all_compile({"crease.vert", "crease.geom", "crease.frag"}, CreaseVariant::all());
  glslang.expect_all_compile({"fullscreen.vert", "crease_coverage.frag"}, std::vector<CreaseVariant>{{}});
  glslang.expect_all_compile({"fullscreen.vert", "downsample.frag"}, DownsampleVariant::all());
  glslang.expect_all_compile({"toon.vert", "layer.frag"}, LayerVariant::all());
}

}  // namespace
}  // namespace toond::render
