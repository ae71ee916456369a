// The C++ mirrors of the shaders' uniform blocks (render/frame/uniform_blocks.h,
// render/frame/shading_block.h) against what the driver reports for the compiled
// programs: a member renamed, moved or retyped on one side only, or a block
// renamed or rebound, fails here, not as wrong colours in a render.
#include <gtest/gtest.h>

#include <string>

#include "gpu/program_cache.h"
#include "render/frame/uniform_blocks.h"
#include "support/gl_context_test.h"
#include "toond_shader_files.h"

namespace toond::render {
namespace {

class UniformBlocks : public test::GlContextTest {};

struct ProgramSpec {
  std::vector<std::string> stages;
  std::vector<std::string> defines;
};

// Programs that between them declare every block (a std140 block's members
// are all active wherever the block is).
const std::vector<ProgramSpec> kPrograms = {
    {{"toon.vert", "toon.frag"},
     {"MODE_CEL", "ROUND_CEIL", "SPECULAR", "RIM", "CONTOUR_EVEN", "HALFTONE_DOTS", "SHADOWS", "HAS_POINT_LIGHTS",
      "LIGHT_COUNT 2", "BAND_AA", "ALPHA_MASK", "HAS_TEXTURE"}},
    {{"toon.vert", "toon.frag"}, {"MODE_CEL", "RAMP", "RAMP_COUNT 3"}},
    {{"hull.vert", "hull.frag"}, {"OUTLINE_MATERIAL"}},
    {{"wire.vert", "wire.geom", "hull.frag"}, {"LINE_SEGMENT"}},
    {{"crease.vert", "crease.geom", "crease.frag"}, {"SAMPLE_MASK"}},
    {{"toon.vert", "normal_depth.frag"}, {"ALPHA_MASK"}},
    {{"shadow.vert", "shadow.frag"}, {"ALPHA_MASK"}},
};

// Checks the block in one program; false when the program has no such block.
bool check_block(GLuint program, const UniformBlockLayout& layout, const std::string& where) {
  const std::string name(layout.name);
  const GLuint block = glGetUniformBlockIndex(program, name.c_str());
  if (block == GL_INVALID_INDEX) return false;
  GLint size = 0;
  glGetActiveUniformBlockiv(program, block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
  EXPECT_EQ(static_cast<std::size_t>(size), layout.size) << name << " in " << where;
  GLint binding = -1;
  glGetActiveUniformBlockiv(program, block, GL_UNIFORM_BLOCK_BINDING, &binding);
  EXPECT_EQ(binding, layout.binding) << name << " in " << where;
  for (const auto& [member, offset] : layout.members) {
    const std::string glsl_name(member);
    const char* names[] = {glsl_name.c_str()};
    GLuint index = GL_INVALID_INDEX;
    glGetUniformIndices(program, 1, names, &index);
    EXPECT_NE(index, GL_INVALID_INDEX) << glsl_name << " is not a member of " << name << " in " << where;
    if (index == GL_INVALID_INDEX) continue;
    GLint gl_offset = -1;
    glGetActiveUniformsiv(program, 1, &index, GL_UNIFORM_OFFSET, &gl_offset);
    EXPECT_EQ(static_cast<std::size_t>(gl_offset), offset) << name << "." << glsl_name << " in " << where;
  }
  return true;
}

TEST_F(UniformBlocks, MatchTheShadersLayout) {
  gpu::ProgramCache programs([](const std::string& name) { return std::string(shader_files::find(name)); });
  for (const UniformBlockLayout& layout : uniform_block_layouts()) {
    int programs_with_it = 0;
    for (const ProgramSpec& spec : kPrograms) {
      std::string where;
      for (const std::string& stage : spec.stages) where += stage + " ";
      programs_with_it += check_block(programs.get(spec.stages, spec.defines).id(), layout, where) ? 1 : 0;
    }
    EXPECT_GT(programs_with_it, 0) << "no program declares the block " << layout.name;
  }
}

}  // namespace
}  // namespace toond::render
