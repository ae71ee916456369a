// The C++ mirror of toon.frag's FrameShading block against what the driver
// reports for the compiled shader: a member renamed, moved or retyped on
// one side only fails here, not as wrong colours in a render.
#include <gtest/gtest.h>

#include <string>

#include "gpu/program_cache.h"
#include "render/passes/shading_block.h"
#include "support/gl_context_test.h"
#include "toond_shader_files.h"

namespace toond::render {
namespace {

class ShadingBlockTest : public test::GlContextTest {};

// Every feature that reads from the block, so no member is unused.
const std::vector<std::string> kEveryReader = {"MODE_CEL",         "ROUND_CEIL",      "SPECULAR",  "RIM",
                                               "CONTOUR_EVEN",     "HALFTONE_DOTS",   "SHADOWS",   "HAS_POINT_LIGHTS",
                                               "LIGHT_COUNT 2",    "BAND_AA"};

TEST_F(ShadingBlockTest, MatchesTheShadersLayout) {
  gpu::ProgramCache programs([](const std::string& name) { return std::string(shader_files::find(name)); });
  for (const std::vector<std::string>& defines :
       {kEveryReader, std::vector<std::string>{"MODE_CEL", "RAMP", "RAMP_COUNT 3"},
        std::vector<std::string>{"MODE_FLAT"}}) {
    gpu::Program& program = programs.get("toon.vert", "toon.frag", defines);
    const GLuint block = glGetUniformBlockIndex(program.id(), "FrameShading");
    ASSERT_NE(block, GL_INVALID_INDEX) << "toon.frag declares no FrameShading block";
    GLint size = 0;
    glGetActiveUniformBlockiv(program.id(), block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    EXPECT_EQ(static_cast<std::size_t>(size), sizeof(ShadingBlock));
    GLint binding = -1;
    glGetActiveUniformBlockiv(program.id(), block, GL_UNIFORM_BLOCK_BINDING, &binding);
    EXPECT_EQ(binding, ShadingBlock::kBinding);
    for (const auto& [name, offset] : shading_block_members()) {
      const std::string glsl_name(name);
      const char* names[] = {glsl_name.c_str()};
      GLuint index = GL_INVALID_INDEX;
      glGetUniformIndices(program.id(), 1, names, &index);
      ASSERT_NE(index, GL_INVALID_INDEX) << glsl_name << " is not a member of FrameShading";
      GLint gl_offset = -1;
      glGetActiveUniformsiv(program.id(), 1, &index, GL_UNIFORM_OFFSET, &gl_offset);
      EXPECT_EQ(static_cast<std::size_t>(gl_offset), offset) << glsl_name;
    }
  }
}

}  // namespace
}  // namespace toond::render
