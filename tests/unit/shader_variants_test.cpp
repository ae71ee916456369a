// Every toon.frag variant of a pairwise cover of the plan's feature choices
// (support/variant_cover.h), built from the same ToonVariant type the plan
// uses, compiles in glslang, the reference GLSL front end: a driver may
// accept what another rejects.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

#include "support/variant_cover.h"

namespace toond::render {
namespace {

struct Compiled {
  int status = -1;
  std::string log;
};

Compiled glslang(const std::vector<std::string>& defines) {
  std::string command = std::string(TOOND_GLSLANG_VALIDATOR) + " -l";
  for (std::string define : defines) {
    // "LIGHT_COUNT 2" is -DLIGHT_COUNT=2 on the command line.
    if (const auto space = define.find(' '); space != std::string::npos) define[space] = '=';
    command += " -D" + define;
  }
  command += " " + std::string(TOOND_SHADER_SOURCE_DIR) + "/toon.frag 2>&1";
  Compiled out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 512> chunk{};
  while (std::fgets(chunk.data(), chunk.size(), pipe.get())) out.log += chunk.data();
  out.status = pclose(pipe.release());
  return out;
}

TEST(ShaderVariants, APairwiseCoverOfThePlansFeaturesCompilesInGlslang) {
  const std::vector<ToonVariant> variants = test::pairwise_toon_variants();
  std::printf("[variants] %zu toon.frag variants cover every pair of feature choices\n", variants.size());
  ASSERT_GE(variants.size(), 24u) << "the cover is at least the two largest dimensions' product (8 × 3)";
  for (const ToonVariant& variant : variants) {
    const std::vector<std::string> defines = variant.defines();
    const Compiled result = glslang(defines);
    std::string named;
    for (const std::string& d : defines) named += d + "; ";
    EXPECT_EQ(result.status, 0) << named << "\n" << result.log;
  }
}

}  // namespace
}  // namespace toond::render
