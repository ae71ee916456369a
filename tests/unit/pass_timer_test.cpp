// Per-pass timing with GPU timer queries, on a real context (llvmpipe on CI).
#include <gtest/gtest.h>

#include <stdexcept>

#include "gpu/render_target.h"
#include "render/frame/pass_timer.h"
#include "render/run/renderer.h"
#include "support/gl_context_test.h"

namespace toond::render {
namespace {

class PassTimerTest : public test::GlContextTest {
 protected:
  // Clears a large target a few times: GPU work the queries can see.
  static std::vector<PassTiming> timed_frame(gpu::RenderTarget& target) {
    std::vector<PassTiming> timings;
    PassTimer timer(timings, true);
    target.bind_for_drawing();
    for (int i = 0; i < 8; ++i) {
      glClearColor(0.1f * i, 0.2f, 0.3f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    timer.mark(Pass::Main);
    (void)target.read_back();
    timer.mark(Pass::Readback);
    timer.mark(Pass::Downsample);
    return timings;
  }
};

TEST_F(PassTimerTest, EveryPassGetsAFigureAndGpuTimesWhereTheDriverHasThem) {
  gpu::RenderTarget target(512, 512, 1);
  timed_frame(target);  // a new context's first queries may be discarded
  const std::vector<PassTiming> t = timed_frame(target);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].pass, "main");
  EXPECT_EQ(t[1].pass, "readback");
  EXPECT_EQ(t[2].pass, "downsample");
  for (const PassTiming& p : t) {
    EXPECT_GE(p.ms, 0.0) << p.pass;
    EXPECT_GE(p.cpu_ms, 0.0) << p.pass;
  }
  const bool gpu = PassTimer::gpu_timers_available();
  EXPECT_EQ(t[0].gpu, gpu);
  EXPECT_EQ(t[1].gpu, gpu);
  EXPECT_FALSE(t[2].gpu) << "after the readback a pass is CPU work";
  EXPECT_EQ(t[2].ms, t[2].cpu_ms);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A render that throws halfway leaves no query running: the next render
// can begin its own.
TEST_F(PassTimerTest, AnAbandonedTimerEndsItsQuery) {
  gpu::RenderTarget target(64, 64, 1);
  try {
    std::vector<PassTiming> timings;
    PassTimer timer(timings, true);
    timer.mark(Pass::Shadow);
    throw std::runtime_error("pass failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const std::vector<PassTiming> t = timed_frame(target);
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A timer told not to count GPU time gives wall-clock figures only, even
// where the driver could count.
TEST_F(PassTimerTest, WithoutGpuTimersEveryFigureIsWallClock) {
  gpu::RenderTarget target(64, 64, 1);
  std::vector<PassTiming> timings;
  {
    PassTimer timer(timings, false);
    glClear(GL_COLOR_BUFFER_BIT);
    timer.mark(Pass::Main);
    (void)target.read_back();
    timer.mark(Pass::Readback);
  }
  ASSERT_EQ(timings.size(), 2u);
  for (const PassTiming& p : timings) {
    EXPECT_FALSE(p.gpu) << p.pass;
    EXPECT_EQ(p.ms, p.cpu_ms) << p.pass;
  }
}

}  // namespace
}  // namespace toond::render
