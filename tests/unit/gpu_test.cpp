// GPU room tests with a real EGL context (llvmpipe on CI).
#include <gtest/gtest.h>

#include "gpu/egl_context.h"
#include "gpu/program.h"
#include "gpu/render_target.h"
#include "gpu/shader_compile_error.h"
#include "support/gl_context_test.h"

namespace toond::gpu {
namespace {

TEST(WithDefines, InsertsAfterVersionAndKeepsLineNumbers) {
  const std::string out = with_defines("#version 430 core\nvoid main() {}\n", {"A", "B 2"});
  EXPECT_EQ(out, "#version 430 core\n#define A\n#define B 2\n#line 2\nvoid main() {}\n");
}

TEST(WithDefines, SourceWithoutVersion) {
  EXPECT_EQ(with_defines("void main() {}\n", {"A"}), "#define A\n#line 1\nvoid main() {}\n");
}

class Gpu : public test::GlContextTest {};

TEST(SoftwareRasterizer, KnowsMesasCpuRasterizersByName) {
  EXPECT_TRUE(software_rasterizer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(software_rasterizer("softpipe"));
  EXPECT_FALSE(software_rasterizer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
  EXPECT_FALSE(software_rasterizer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)"));
  EXPECT_FALSE(software_rasterizer(""));
}

TEST_F(Gpu, ContextIsCoreFourThreeOrNewer) {
  const GlInfo& info = context().info();
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_TRUE(info.major > 4 || (info.major == 4 && info.minor >= 3)) << info.version;
  EXPECT_FALSE(info.platform.empty());
}

TEST_F(Gpu, ForcingAMissingDeviceFailsWithAClearMessage) {
  try {
    EglContext bad(EglContext::Options{999});
    FAIL() << "device 999 accepted";
  } catch (const GpuError& e) {
    EXPECT_NE(std::string(e.what()).find("999"), std::string::npos) << e.what();
  }
}

// Clearing to a linear value and reading back gives its sRGB encoding: the
// framebuffer really is sRGB, for single-sample and multisampled targets.
TEST_F(Gpu, RenderTargetEncodesSrgbOnWrite) {
  for (int samples : {1, 4}) {
    RenderTarget target(8, 4, samples);
    target.bind_for_drawing();
    glEnable(GL_FRAMEBUFFER_SRGB);
    glClearColor(0.2140f, 1.0f, 0.0f, 1.0f);  // linear 0.214 is sRGB 0.5
    glClear(GL_COLOR_BUFFER_BIT);
    const image::Image img = target.read_back();
    ASSERT_EQ(img.width, 8);
    ASSERT_EQ(img.height, 4);
    EXPECT_NEAR(img.pixel(3, 2)[0], 128, 1) << samples << " samples";
    EXPECT_EQ(img.pixel(3, 2)[1], 255);
    EXPECT_EQ(img.pixel(3, 2)[2], 0);
    EXPECT_EQ(img.pixel(3, 2)[3], 255);
  }
}

TEST_F(Gpu, ReadBackReturnsTopRowFirst) {
  RenderTarget target(4, 4, 1);
  target.bind_for_drawing();
  glDisable(GL_FRAMEBUFFER_SRGB);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 3, 4, 1);  // GL's top row is y = 3
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const image::Image img = target.read_back();
  EXPECT_EQ(img.pixel(0, 0)[0], 255);
  EXPECT_EQ(img.pixel(0, 3)[0], 0);
}

// Both readback paths: every frame read must be that frame's (a persistently
// mapped pixel buffer still holds the previous one), rows must not be padded
// to four bytes at odd widths, and the resolve must reach them for
// multisampled targets.
TEST_F(Gpu, ReadBackSeesEachFrameAtOddSizes) {
  using Case = std::pair<ReadbackPath, int>;  // the path, samples
  for (const auto& [path, samples] : {Case{ReadbackPath::PixelBuffer, 1}, Case{ReadbackPath::PixelBuffer, 4},
                                      Case{ReadbackPath::ClientMemory, 1}, Case{ReadbackPath::ClientMemory, 4}}) {
    SCOPED_TRACE(path == ReadbackPath::PixelBuffer ? "pixel buffer" : "client memory");
    RenderTarget target(7, 5, samples, path);
    for (int frame = 0; frame < 3; ++frame) {
      target.bind_for_drawing();
      glDisable(GL_FRAMEBUFFER_SRGB);
      glEnable(GL_SCISSOR_TEST);
      auto value = [&](int gl_row) { return frame * 60 + gl_row * 11 + 3; };
      for (int y = 0; y < 5; ++y) {
        glScissor(0, y, 7, 1);
        glClearColor(static_cast<float>(value(y)) / 255.0f, 0.0f, static_cast<float>(6 - y) / 255.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
      }
      glDisable(GL_SCISSOR_TEST);
      const image::Image img = target.read_back();
      ASSERT_EQ(img.rgba.size(), 7u * 5u * 4u);
      for (int row = 0; row < 5; ++row) {
        for (int x = 0; x < 7; ++x) {
          ASSERT_EQ(img.pixel(x, row)[0], value(4 - row))
              << samples << " samples, frame " << frame << " (" << x << "," << row << ")";
          ASSERT_EQ(img.pixel(x, row)[2], 6 - (4 - row));
          ASSERT_EQ(img.pixel(x, row)[3], 255);
        }
      }
    }
  }
}

TEST_F(Gpu, ShaderErrorNamesTheFileAndKeepsTheLog) {
  const ShaderSource vs{"ok.vert", "#version 430 core\nvoid main() { gl_Position = vec4(0); }\n"};
  const ShaderSource fs{"broken.frag", "#version 430 core\nout vec4 c;\nvoid main() { c = oops; }\n"};
  try {
    Program p(vs, fs, {});
    FAIL() << "a broken shader compiled";
  } catch (const ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "broken.frag");
    EXPECT_FALSE(e.log().empty());
  }
}

}  // namespace
}  // namespace toond::gpu
