// Shader hot reload (--shader-dir): reading driver logs, noticing edits in a
// shader folder, and the program cache swapping programs only when an edit
// compiles.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "app/options.h"
#include "gpu/egl_context.h"
#include "gpu/program_cache.h"
#include "gpu/shader_compile_error.h"
#include "gpu/shader_log.h"
#include "gpu/shader_source.h"

namespace toond::gpu {
namespace {

namespace fs = std::filesystem;

// ---- driver logs -----------------------------------------------------------

TEST(ShaderLog, MesaLineAndMessage) {
  const auto e = first_shader_error("0:12(5): error: syntax error, unexpected ';'\n");
  ASSERT_TRUE(e.line.has_value());
  EXPECT_EQ(*e.line, 12);
  EXPECT_EQ(e.text, "syntax error, unexpected ';'");
}

TEST(ShaderLog, MesaPreprocessorError) {
  const auto e = first_shader_error("0:3(1): preprocessor error: Unterminated #if\n");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.text, "Unterminated #if");
}

TEST(ShaderLog, NvidiaLineAndMessage) {
  const auto e = first_shader_error(
      "0(241) : error C0000: syntax error, unexpected ';', expecting \"::\" at token \";\"\n"
      "0(242) : error C1503: undefined variable \"x\"\n");
  EXPECT_EQ(e.line, 241);
  EXPECT_EQ(e.text, "syntax error, unexpected ';', expecting \"::\" at token \";\"");
}

TEST(ShaderLog, GlslangStyle) {
  const auto e = first_shader_error("ERROR: 0:7: 'oops' : undeclared identifier \nERROR: 1 compilation errors.\n");
  EXPECT_EQ(e.line, 7);
  EXPECT_EQ(e.text, "'oops' : undeclared identifier");
}

TEST(ShaderLog, TheFirstErrorWinsOverEarlierWarnings) {
  const auto mesa = first_shader_error("0:4(10): warning: `x' used uninitialized\n0:9(3): error: `y' undeclared\n");
  EXPECT_EQ(mesa.line, 9);
  EXPECT_EQ(mesa.text, "`y' undeclared");
  const auto nvidia = first_shader_error(
      "0(4) : warning C7050: \"x\" might be used before being initialized\n"
      "0(9) : error C1008: undefined variable \"y\"\n");
  EXPECT_EQ(nvidia.line, 9);
  EXPECT_EQ(nvidia.text, "undefined variable \"y\"");
}

TEST(ShaderLog, OnlyWarningsGiveTheFirstWarning) {
  const auto e = first_shader_error("0:4(10): warning: `x' used uninitialized\n");
  EXPECT_EQ(e.line, 4);
}

TEST(ShaderLog, LinkErrorsHaveNoLine) {
  const auto e =
      first_shader_error("error: fragment shader input `v_normal' has no matching output in the previous stage\n");
  EXPECT_FALSE(e.line.has_value());
  EXPECT_EQ(e.text, "fragment shader input `v_normal' has no matching output in the previous stage");
}

TEST(ShaderLog, UnknownFormatGivesTheFirstLine) {
  const auto e = first_shader_error("\n  something went wrong\r\nmore\n");
  EXPECT_FALSE(e.line.has_value());
  EXPECT_EQ(e.text, "something went wrong");
  EXPECT_FALSE(first_shader_error("").line.has_value());
}

// ---- a folder of shader files ----------------------------------------------

fs::path temp_dir() {
  std::random_device rd;
  for (;;) {
    auto dir = fs::temp_directory_path() / ("toond-shader-source-" + std::to_string(rd()));
    if (fs::create_directory(dir)) return dir;
  }
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

class ShaderDirectoryTest : public ::testing::Test {
 protected:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path dir_ = temp_dir();
};

TEST_F(ShaderDirectoryTest, RejectsAMissingFolder) {
  EXPECT_THROW(ShaderDirectory(dir_ / "nope"), std::invalid_argument);
}

TEST_F(ShaderDirectoryTest, AMissingFileIsAnErrorNamingIt) {
  ShaderDirectory sources(dir_);
  try {
    sources.read("toon.frag");
    FAIL() << "a missing file was read";
  } catch (const ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "toon.frag");
    EXPECT_NE(e.log().find("toon.frag"), std::string::npos) << e.log();
  }
  EXPECT_THROW(sources.read("../escape.frag"), ShaderCompileError);
}

TEST_F(ShaderDirectoryTest, NoticesEditsWithinTheSameSecond) {
  write(dir_ / "a.frag", "one\n");
  write(dir_ / "b.frag", "bee\n");
  ShaderDirectory sources(dir_);
  EXPECT_TRUE(sources.can_change());
  EXPECT_EQ(sources.read("a.frag"), "one\n");
  EXPECT_EQ(sources.read("b.frag"), "bee\n");
  EXPECT_TRUE(sources.changed().empty());

  // Same size, written right away: only the content tells.
  write(dir_ / "a.frag", "two\n");
  EXPECT_EQ(sources.changed(), std::vector<std::string>{"a.frag"});
  EXPECT_EQ(sources.changed(), std::vector<std::string>{"a.frag"}) << "changed() alone does not consume an edit";
  EXPECT_EQ(sources.read("a.frag"), "two\n");
  EXPECT_TRUE(sources.changed().empty());

  // Rewriting the same bytes (or touching) is no change.
  write(dir_ / "b.frag", "bee\n");
  EXPECT_TRUE(sources.changed().empty());
}

TEST_F(ShaderDirectoryTest, ReplacedByRenameIsAChange) {
  write(dir_ / "a.frag", "one\n");
  ShaderDirectory sources(dir_);
  sources.read("a.frag");
  write(dir_ / "a.frag.tmp", "uno\n");
  fs::rename(dir_ / "a.frag.tmp", dir_ / "a.frag");
  EXPECT_EQ(sources.changed(), std::vector<std::string>{"a.frag"});
}

TEST_F(ShaderDirectoryTest, DeletionAndReturnAreChanges) {
  write(dir_ / "a.frag", "one\n");
  ShaderDirectory sources(dir_);
  sources.read("a.frag");
  fs::remove(dir_ / "a.frag");
  EXPECT_EQ(sources.changed(), std::vector<std::string>{"a.frag"});
  EXPECT_THROW(sources.read("a.frag"), ShaderCompileError);
  EXPECT_TRUE(sources.changed().empty()) << "still missing is no news";
  write(dir_ / "a.frag", "back\n");
  EXPECT_EQ(sources.changed(), std::vector<std::string>{"a.frag"});
}

TEST(FixedShaderSources, NeverChange) {
  FixedShaderSources sources([](const std::string& name) { return "text of " + name; });
  EXPECT_FALSE(sources.can_change());
  EXPECT_EQ(sources.read("x.frag"), "text of x.frag");
  EXPECT_TRUE(sources.changed().empty());
}

// ---- the program cache reloading, with a real context ------------------------

const char* kVert =
    "#version 430 core\nout vec3 v_tint;\nvoid main() { v_tint = vec3(1.0); gl_Position = vec4(0.0); }\n";
const char* kFrag =
    "#version 430 core\nin vec3 v_tint;\nout vec4 o_color;\nvoid main() { o_color = vec4(v_tint, 1.0); }\n";

class ShaderReload : public ShaderDirectoryTest {
 protected:
  static void SetUpTestSuite() { context_ = new EglContext(EglContext::Options{}); }
  static void TearDownTestSuite() {
    delete context_;
    context_ = nullptr;
  }
  static inline EglContext* context_ = nullptr;

  void SetUp() override {
    write(dir_ / "t.vert", kVert);
    write(dir_ / "t.frag", kFrag);
  }
};

TEST_F(ShaderReload, EmbeddedSourcesNeverReload) {
  int reads = 0;
  ProgramCache cache([&](const std::string& name) {
    ++reads;
    return std::string(name == "t.vert" ? kVert : kFrag);
  });
  const GLuint id = cache.get("t.vert", "t.frag", {}).id();
  EXPECT_EQ(cache.refresh().programs, 0u);
  EXPECT_EQ(cache.get("t.vert", "t.frag", {}).id(), id);
  EXPECT_EQ(reads, 2);
}

TEST_F(ShaderReload, AnEditRebuildsEveryVariantUsingTheFile) {
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  const GLuint plain = cache.get("t.vert", "t.frag", {}).id();
  const GLuint variant = cache.get("t.vert", "t.frag", {"FEATURE"}).id();
  EXPECT_TRUE(cache.refresh().files.empty());
  EXPECT_EQ(cache.get("t.vert", "t.frag", {}).id(), plain);

  write(dir_ / "t.frag", std::string(kFrag) + "// edited\n");
  const auto reload = cache.refresh();
  EXPECT_EQ(reload.files, std::vector<std::string>{"t.frag"});
  EXPECT_EQ(reload.programs, 2u);
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_NE(cache.get("t.vert", "t.frag", {}).id(), plain);
  EXPECT_NE(cache.get("t.vert", "t.frag", {"FEATURE"}).id(), variant);
}

TEST_F(ShaderReload, AnEditedModuleRebuildsTheProgramsThatIncludeIt) {
  write(dir_ / "tint.glsl", "vec3 tint() { return vec3(1.0); }\n");
  write(dir_ / "m.frag",
        "#version 430 core\nout vec4 o_color;\n#include \"tint.glsl\"\nvoid main() { o_color = vec4(tint(), 1.0); }\n");
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  const GLuint with_module = cache.get("t.vert", "m.frag", {}).id();
  const GLuint without = cache.get("t.vert", "t.frag", {}).id();

  write(dir_ / "tint.glsl", "vec3 tint() { return vec3(0.5); }\n");
  const auto reload = cache.refresh();
  EXPECT_EQ(reload.files, std::vector<std::string>{"tint.glsl"});
  EXPECT_EQ(reload.programs, 1u);
  EXPECT_NE(cache.get("t.vert", "m.frag", {}).id(), with_module);
  EXPECT_EQ(cache.get("t.vert", "t.frag", {}).id(), without);

  // An error inside the module names the module and its own line.
  write(dir_ / "tint.glsl", "// tint\nvec3 tint() { return ; }\n");
  try {
    cache.refresh();
    FAIL() << "a broken module was accepted";
  } catch (const ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "tint.glsl") << e.log();
    EXPECT_EQ(first_shader_error(e.log()).line, 2) << e.log();
  }
}

TEST_F(ShaderReload, AnEditMayIncludeAModuleNoProgramUsedYet) {
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  const GLuint before = cache.get("t.vert", "t.frag", {}).id();
  write(dir_ / "half.glsl", "vec3 half_of(vec3 v) { return 0.5 * v; }\n");
  write(dir_ / "t.frag",
        "#version 430 core\nin vec3 v_tint;\nout vec4 o_color;\n#include \"half.glsl\"\n"
        "void main() { o_color = vec4(half_of(v_tint), 1.0); }\n");
  EXPECT_EQ(cache.refresh().programs, 1u);
  EXPECT_NE(cache.get("t.vert", "t.frag", {}).id(), before);
  // The module is watched from now on.
  write(dir_ / "half.glsl", "vec3 half_of(vec3 v) { return 0.25 * v; }\n");
  EXPECT_EQ(cache.refresh().files, std::vector<std::string>{"half.glsl"});
}

TEST_F(ShaderReload, AUniformNoSourceDeclaresIsAnErrorAndAnInactiveOneIsNot) {
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  write(dir_ / "u.frag",
        "#version 430 core\nout vec4 o_color;\nuniform float u_used;\nuniform float u_unused;\n"
        "void main() { o_color = vec4(u_used); }\n");
  Program& program = cache.get("t.vert", "u.frag", {});
  EXPECT_NO_THROW(program.set("u_used", 1.0f));
  EXPECT_NO_THROW(program.set("u_unused", 1.0f));  // declared, optimised away by this variant
  EXPECT_THROW(program.set("u_usde", 1.0f), GpuError);
}

TEST_F(ShaderReload, ABrokenEditReportsOnceAndKeepsThePreviousProgram) {
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  const GLuint good = cache.get("t.vert", "t.frag", {}).id();

  // Line 4 of the file (the #defines inserted by with_defines do not shift it).
  write(dir_ / "t.frag", "#version 430 core\nin vec3 v_tint;\nout vec4 o_color;\nvoid main() { o_color = ; }\n");
  try {
    cache.refresh();
    FAIL() << "a broken edit was accepted";
  } catch (const ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "t.frag");
    EXPECT_EQ(first_shader_error(e.log()).line, 4) << e.log();
  }
  // The error came back once; the old program keeps serving.
  EXPECT_TRUE(cache.refresh().files.empty());
  EXPECT_EQ(cache.get("t.vert", "t.frag", {}).id(), good);
  // A new variant is built from the last good text too.
  EXPECT_NO_THROW(cache.get("t.vert", "t.frag", {"OTHER"}));

  write(dir_ / "t.frag", std::string(kFrag) + "// fixed\n");
  const auto reload = cache.refresh();
  EXPECT_EQ(reload.files, std::vector<std::string>{"t.frag"});
  EXPECT_EQ(reload.programs, 2u);
  EXPECT_NE(cache.get("t.vert", "t.frag", {}).id(), good);
}

TEST_F(ShaderReload, EditsToBothStagesAreTakenTogether) {
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  cache.get("t.vert", "t.frag", {});
  // Renaming the varying in one stage alone would not link.
  auto renamed = [](std::string s) {
    for (auto at = s.find("v_tint"); at != std::string::npos; at = s.find("v_tint")) s.replace(at, 6, "v_col");
    return s;
  };
  write(dir_ / "t.vert", renamed(kVert));
  write(dir_ / "t.frag", renamed(kFrag));
  const auto reload = cache.refresh();
  EXPECT_EQ(reload.files, (std::vector<std::string>{"t.frag", "t.vert"}));
  EXPECT_EQ(reload.programs, 1u);
}

TEST_F(ShaderReload, AFixInTheOtherStageCompletesAnEarlierEdit) {
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  const GLuint good = cache.get("t.vert", "t.frag", {}).id();
  // The fragment stage alone compiles but no longer links: v_tint is
  // integer here and float in the vertex stage. (Drivers differ on milder
  // mismatches: some link a fragment input no vertex output writes, or a
  // vec3 output read as a vec4, and read what is missing as undefined.)
  write(dir_ / "t.frag",
        "#version 430 core\nflat in ivec3 v_tint;\nout vec4 o_color;\nvoid main() { o_color = vec4(v_tint, 1.0); }\n");
  EXPECT_THROW(cache.refresh(), ShaderCompileError);
  EXPECT_EQ(cache.get("t.vert", "t.frag", {}).id(), good);
  write(dir_ / "t.vert",
        "#version 430 core\nflat out ivec3 v_tint;\nvoid main() { v_tint = ivec3(1); gl_Position = vec4(0.0); }\n");
  const auto reload = cache.refresh();
  EXPECT_EQ(reload.files, (std::vector<std::string>{"t.frag", "t.vert"}));
  EXPECT_NE(cache.get("t.vert", "t.frag", {}).id(), good);
}

TEST_F(ShaderReload, ADeletedFileIsReportedAndThePreviousProgramServes) {
  ProgramCache cache(std::make_unique<ShaderDirectory>(dir_));
  const GLuint good = cache.get("t.vert", "t.frag", {}).id();
  fs::remove(dir_ / "t.frag");
  try {
    cache.refresh();
    FAIL() << "a deleted file went unnoticed";
  } catch (const ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "t.frag");
  }
  EXPECT_TRUE(cache.refresh().files.empty());
  EXPECT_EQ(cache.get("t.vert", "t.frag", {}).id(), good);
  write(dir_ / "t.frag", kFrag);  // back as it was: nothing to rebuild
  EXPECT_TRUE(cache.refresh().files.empty());
  EXPECT_EQ(cache.get("t.vert", "t.frag", {}).id(), good);
}

}  // namespace
}  // namespace toond::gpu

namespace toond::app {
namespace {

TEST(ShaderDirOption, ParsedListedAndEmbeddedByDefault) {
  EXPECT_TRUE(parse_options({}).shader_dir.empty());
  EXPECT_EQ(parse_options({"--shader-dir", "/tmp/shaders"}).shader_dir, "/tmp/shaders");
  EXPECT_THROW(parse_options({"--shader-dir"}), std::invalid_argument);
  EXPECT_THROW(parse_options({"--shader-dir", ""}), std::invalid_argument);
  EXPECT_NE(usage().find("--shader-dir"), std::string::npos);
}

}  // namespace
}  // namespace toond::app
