// The render threads' and the GPU's failures leave the pipeline's entry as
// RenderFailure (pipeline/render_failure.h), and the HTTP layer, which
// knows no GPU, answers each as it answered the exception itself: the same
// status, code, message and Retry-After.
#include <gtest/gtest.h>

#include <exception>
#include <stdexcept>
#include <string>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "gpu/gpu_error.h"
#include "gpu/shader_compile_error.h"
#include "http/error_response.h"
#include "pipeline/render_failure.h"
#include "render/frame/draw_pacing.h"
#include "render/run/render_service.h"

namespace toond {
namespace {

using nlohmann::json;

struct Answered {
  int status = 0;
  std::string retry_after;
  json error;
};

// `error` said by the entry, then answered by the HTTP layer.
Answered answer_of(const std::exception_ptr& error) {
  httplib::Response res;
  try {
    pipeline::rethrow_as_render_failure(error);
  } catch (const pipeline::RenderFailure&) {
    http::write_exception(res, std::current_exception());
  }
  return {res.status, res.get_header_value("Retry-After"), json::parse(res.body).at("error")};
}

TEST(RenderFailureAnswer, EachFailureKeepsItsStatusCodeMessageAndRetry) {
  struct Case {
    std::exception_ptr error;
    int status;
    const char* retry_after;
    const char* code;
    const char* message;
  };
  const Case cases[] = {
      {std::make_exception_ptr(render::DeadlineExceeded()), 503, "5", "deadline_exceeded",
       "the render's deadline (--render-timeout) passed while it waited in the queue"},
      {std::make_exception_ptr(render::RenderAborted("the line drawing passed its deadline")), 503, "5",
       "render_aborted",
       "the line drawing passed its deadline: it ran past --render-timeout; a smaller size, fewer samples or fewer "
       "outline passes draw sooner (the answer's X-Toond-Cost header and --max-render-cost price a request)"},
      {std::make_exception_ptr(render::QueueFull()), 503, "1", "busy", "render queue is full; retry shortly"},
      {std::make_exception_ptr(gpu::GpuReset("the GL context was lost")), 503, "1", "gpu_reset",
       "the GL context was lost"},
      {std::make_exception_ptr(gpu::GpuError("framebuffer incomplete")), 500, "", "gpu_error",
       "framebuffer incomplete"},
  };
  for (const Case& c : cases) {
    const Answered a = answer_of(c.error);
    EXPECT_EQ(a.status, c.status) << c.code;
    EXPECT_EQ(a.retry_after, c.retry_after) << c.code;
    EXPECT_EQ(a.error.at("code"), c.code);
    EXPECT_EQ(a.error.at("message"), c.message) << c.code;
  }
}

TEST(RenderFailureAnswer, TheDeadlinesFlagIsNamedWhereTheRenderLayerDoesNotKnowIt) {
  EXPECT_EQ(std::string(render::DeadlineExceeded().what()).find("--"), std::string::npos);
}

TEST(RenderFailureAnswer, AShaderErrorNamesItsFileItsLineAndTheLog) {
  const std::string log = "0:12(5): error: syntax error, unexpected ';'\n";
  const Answered a = answer_of(std::make_exception_ptr(gpu::ShaderCompileError("toon.frag", log)));
  EXPECT_EQ(a.status, 500);
  EXPECT_EQ(a.retry_after, "");
  EXPECT_EQ(a.error.at("code"), "shader_error");
  EXPECT_EQ(a.error.at("message"), "toon.frag:12: syntax error, unexpected ';'");
  EXPECT_EQ(a.error.at("path"), "toon.frag");
  EXPECT_EQ(a.error.at("log"), log);
  EXPECT_EQ(a.error.at("line"), 12);
}

TEST(RenderFailureAnswer, AShaderLogWithNothingInItStillNamesTheFile) {
  const Answered a = answer_of(std::make_exception_ptr(gpu::ShaderCompileError("edge.vert", "")));
  EXPECT_EQ(a.status, 500);
  EXPECT_EQ(a.error.at("message"), "edge.vert: does not compile");
  EXPECT_FALSE(a.error.contains("line"));
}

TEST(RenderFailure, OtherExceptionsPassAsThemselves) {
  EXPECT_THROW(pipeline::rethrow_as_render_failure(std::make_exception_ptr(std::invalid_argument("x"))),
               std::invalid_argument);
}

}  // namespace
}  // namespace toond
