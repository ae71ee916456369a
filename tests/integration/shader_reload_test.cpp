// `toond --shader-dir DIR`: GLSL read from disk, recompiled when a file
// changes; a broken edit answers one JSON shader_error (file and line) and
// the previous program keeps serving.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/daemon.h"
#include "test_client.h"

namespace toond::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

// A copy of the source tree's shaders in a fresh folder.
fs::path copy_shaders() {
  const fs::path dir = make_temp_dir("toond-shaders");
  for (const auto& entry : fs::directory_iterator(TOOND_SHADER_SOURCE_DIR)) {
    const auto ext = entry.path().extension();
    if (ext == ".vert" || ext == ".frag" || ext == ".geom" || ext == ".glsl")
      fs::copy_file(entry.path(), dir / entry.path().filename());
  }
  return dir;
}

// `text` with `line` inserted before main()'s closing brace (the last "}" of
// the file); `*inserted_at` gets the 1-based number of the new line.
std::string insert_before_last_brace(const std::string& text, const std::string& line, int* inserted_at = nullptr) {
  const auto brace = text.rfind('}');
  EXPECT_NE(brace, std::string::npos);
  const auto line_start = text.rfind('\n', brace) + 1;  // npos + 1 == 0
  if (inserted_at) *inserted_at = 1 + static_cast<int>(std::count(text.begin(), text.begin() + line_start, '\n'));
  return text.substr(0, line_start) + line + "\n" + text.substr(line_start);
}

std::size_t differing_pixels(const image::Image& a, const image::Image& b) {
  if (a.width != b.width || a.height != b.height) return static_cast<std::size_t>(-1);
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (!std::equal(a.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                    a.rgba.begin() + static_cast<std::ptrdiff_t>(i + 4),
                    b.rgba.begin() + static_cast<std::ptrdiff_t>(i))) {
      ++n;
    }
  }
  return n;
}

class ShaderReload : public ::testing::Test {
 protected:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path dir_ = copy_shaders();
  const json params_ = {{"width", 96}, {"height", 96}};
};

TEST_F(ShaderReload, EditsRenderBrokenEditsReportFileAndLineAndThePreviousProgramServes) {
  Daemon daemon({}, {"--shader-dir", dir_.string()});
  auto client = daemon.client();
  const fs::path frag = dir_ / "toon.frag";
  const std::string original = read_text(frag);

  const image::Image before = render_ok(client, params_);
  ASSERT_GT(before.width, 0);

  // 1. An edit that compiles shows up in the next render: the model's
  // colours inverted.
  const std::string inverted = insert_before_last_brace(original, "  o_color.rgb = vec3(1.0) - o_color.rgb;");
  write_text(frag, inverted);
  const image::Image edited = render_ok(client, params_);
  EXPECT_GT(differing_pixels(before, edited), 96u * 96u / 10) << "the edit did not change the image";

  // 2. An edit that does not compile: that request gets the error, with the
  // file and the line of the file (written right after the previous one,
  // within the same second).
  int broken_line = 0;
  write_text(frag, insert_before_last_brace(inverted, "  float broken = ;", &broken_line));
  auto res = post_json(client, "/render", params_);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 500) << res->body;
  const json error = error_of(res);
  EXPECT_EQ(error.value("code", ""), "shader_error") << res->body;
  EXPECT_EQ(error.value("path", ""), "toon.frag") << res->body;
  EXPECT_EQ(error.value("line", 0), broken_line) << res->body;
  EXPECT_NE(error.value("message", "").find("toon.frag:" + std::to_string(broken_line)), std::string::npos)
      << res->body;

  // 3. Until the file changes again, the previous (edited) program serves.
  for (int i = 0; i < 2; ++i) {
    const image::Image still = render_ok(client, params_);
    EXPECT_EQ(differing_pixels(edited, still), 0u) << "request " << i << " after the broken edit";
  }

  // 4. Fixed (here: back to the original): renders as at the start.
  write_text(frag, original);
  const image::Image fixed = render_ok(client, params_);
  EXPECT_EQ(differing_pixels(before, fixed), 0u);
}

TEST_F(ShaderReload, AModuleEditRendersAndABrokenOneIsReportedAtItsOwnLine) {
  Daemon daemon({}, {"--shader-dir", dir_.string()});
  auto client = daemon.client();
  const fs::path module = dir_ / "toon_contour.glsl";
  const std::string original = read_text(module);
  const image::Image before = render_ok(client, params_);
  ASSERT_GT(before.width, 0);

  // apply_contour inverts every colour before it returns.
  const std::size_t at = original.rfind("return color;");
  ASSERT_NE(at, std::string::npos);
  auto with_line = [&](const std::string& text, const std::string& line) {
    return text.substr(0, at) + line + "\n  " + text.substr(at);
  };
  write_text(module, with_line(original, "color = vec3(1.0) - color;"));
  const image::Image edited = render_ok(client, params_);
  EXPECT_GT(differing_pixels(before, edited), 96u * 96u / 10) << "the module's edit did not change the image";

  write_text(module, with_line(original, "float broken = ;"));
  const int broken_line =
      1 + static_cast<int>(std::count(original.begin(), original.begin() + static_cast<long>(at), '\n'));
  auto res = post_json(client, "/render", params_);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 500) << res->body;
  const json error = error_of(res);
  EXPECT_EQ(error.value("path", ""), "toon_contour.glsl") << res->body;
  EXPECT_EQ(error.value("line", 0), broken_line) << res->body;

  write_text(module, original);
  EXPECT_EQ(differing_pixels(before, render_ok(client, params_)), 0u);
}

TEST_F(ShaderReload, AMissingFileInTheFolderIsAnErrorNamingIt) {
  fs::remove(dir_ / "toon.frag");
  Daemon daemon({}, {"--shader-dir", dir_.string()});
  auto client = daemon.client();
  auto res = post_json(client, "/render", params_);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 500) << res->body;
  const json error = error_of(res);
  EXPECT_EQ(error.value("code", ""), "shader_error") << res->body;
  EXPECT_EQ(error.value("path", ""), "toon.frag") << res->body;
  // The answer names the file, not where the daemon reads it from.
  EXPECT_EQ(res->body.find(dir_.string()), std::string::npos) << res->body;

  // Putting it there is enough: nothing was cached from the failed attempt.
  fs::copy_file(fs::path(TOOND_SHADER_SOURCE_DIR) / "toon.frag", dir_ / "toon.frag");
  render_ok(client, params_);
}

TEST_F(ShaderReload, AShaderDirThatIsNotAFolderStopsStartUp) {
  const auto missing = run_process({TOOND_BINARY, "--listen", "127.0.0.1:0", "--shader-dir", (dir_ / "nope").string()});
  EXPECT_EQ(missing.status, 2) << missing.err;
  EXPECT_NE(missing.err.find("--shader-dir"), std::string::npos) << missing.err;
  const auto file =
      run_process({TOOND_BINARY, "--listen", "127.0.0.1:0", "--shader-dir", (dir_ / "toon.frag").string()});
  EXPECT_EQ(file.status, 2) << file.err;
  EXPECT_NE(file.err.find("not a directory"), std::string::npos) << file.err;
}

}  // namespace
}  // namespace toond::test
