// GLSL modules: #include lines expanded once per stage, numbered so a
// driver's error names the module's own line, and their errors located in
// the file that asked for them. Pure text; no GL.
#include <gtest/gtest.h>

#include <map>

#include "gpu/shader_compile_error.h"
#include "gpu/shader_includes.h"
#include "gpu/shader_log.h"

namespace toond::gpu {
namespace {

ShaderTextReader files(std::map<std::string, std::string> texts) {
  return [texts = std::move(texts)](const std::string& name) {
    const auto it = texts.find(name);
    if (it == texts.end()) throw ShaderCompileError(name, "cannot read " + name + ": no such file");
    return it->second;
  };
}

TEST(ShaderIncludes, AModuleIsPastedWithLineDirectivesThatNumberItsOwnLines) {
  const ExpandedShader out =
      expand_includes("a.frag", files({{"a.frag", "#version 430 core\n#include \"m.glsl\"\nvoid main() {}\n"},
                                       {"m.glsl", "float f() { return 1.0; }\n"}}));
  EXPECT_EQ(out.text,
            "#version 430 core\n"
            "#line 1 1\n"
            "float f() { return 1.0; }\n"
            "#line 3 0\n"
            "void main() {}\n");
  EXPECT_EQ(out.files, (std::vector<std::string>{"a.frag", "m.glsl"}));
}

TEST(ShaderIncludes, AModuleAskedForTwiceOrByAnotherModuleIsPastedOnce) {
  const ExpandedShader out = expand_includes(
      "a.frag", files({{"a.frag", "#version 430 core\n#include \"b.glsl\"\n  #  include \"c.glsl\"  \n"},
                       {"b.glsl", "#include \"c.glsl\"\nB\n"},
                       {"c.glsl", "C\n"}}));
  EXPECT_EQ(out.files, (std::vector<std::string>{"a.frag", "b.glsl", "c.glsl"}));
  EXPECT_EQ(out.text,
            "#version 430 core\n"
            "#line 1 1\n"
            "#line 1 2\n"
            "C\n"
            "#line 2 1\n"
            "B\n"
            "#line 3 0\n"
            "#line 4 0\n");
}

TEST(ShaderIncludes, AFileWithoutIncludesIsUnchanged) {
  const std::string text = "#version 430 core\n// #include in a comment is still one\nvoid main() {}\n";
  EXPECT_EQ(expand_includes("a.vert", files({{"a.vert", "#version 430 core\nvoid main() {}\n"}})).text,
            "#version 430 core\nvoid main() {}\n");
  // A line that merely mentions the word is not an include.
  EXPECT_EQ(expand_includes("a.vert", files({{"a.vert", text}})).text, text);
}

TEST(ShaderIncludes, AMissingModuleIsAnErrorAtTheIncludingLine) {
  try {
    expand_includes("a.frag", files({{"a.frag", "#version 430 core\n\n#include \"gone.glsl\"\n"}}));
    FAIL() << "a missing module was accepted";
  } catch (const ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "a.frag");
    const ShaderLogError first = first_shader_error(e.log());
    EXPECT_EQ(first.line, 3) << e.log();
    EXPECT_NE(first.text.find("gone.glsl"), std::string::npos) << e.log();
  }
}

TEST(ShaderIncludes, AnIncludeWithoutOneQuotedNameIsAnError) {
  for (const std::string line : {"#include <m.glsl>", "#include m.glsl", "#include \"m.glsl", "#include \"a\" \"b\""}) {
    try {
      expand_includes("a.frag", files({{"a.frag", "#version 430 core\n" + line + "\n"}, {"m.glsl", ""}}));
      ADD_FAILURE() << line << " was accepted";
    } catch (const ShaderCompileError& e) {
      EXPECT_EQ(e.file(), "a.frag");
      EXPECT_EQ(first_shader_error(e.log()).line, 2) << line << ": " << e.log();
    }
  }
}

TEST(ShaderLog, TheSourceStringNumberIsKept) {
  EXPECT_EQ(first_shader_error("3:12(5): error: syntax error\n").source, 3);
  EXPECT_EQ(first_shader_error("2(7) : error C0000: syntax error\n").source, 2);
  EXPECT_EQ(first_shader_error("ERROR: 4:7: 'x' : undeclared identifier\n").source, 4);
  EXPECT_FALSE(first_shader_error("error: linking failed\n").source.has_value());
}

}  // namespace
}  // namespace toond::gpu
