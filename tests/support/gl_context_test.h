#pragma once
// A test suite that needs a real GL context (llvmpipe on CI) shares one,
// made current on the test thread the way the render thread makes its own.
#include <gtest/gtest.h>

#include "gpu/egl_context.h"

namespace toond::test {

class GlContextTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = new gpu::EglContext(gpu::EglContext::Options{}); }
  static void TearDownTestSuite() {
    delete context_;
    context_ = nullptr;
  }
  static const gpu::EglContext& context() { return *context_; }

 private:
  static inline gpu::EglContext* context_ = nullptr;
};

}  // namespace toond::test
