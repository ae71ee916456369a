#include "pipeline/render_failure.h"

#include "gpu/gpu_error.h"
#include "gpu/shader_compile_error.h"
#include "gpu/shader_log.h"
#include "render/frame/draw_pacing.h"
#include "render/run/render_service.h"

namespace toond::pipeline {
namespace {

RenderFailure shader_failure(const gpu::ShaderCompileError& e) {
  const gpu::ShaderLogError first = gpu::first_shader_error(e.log());
  return RenderFailure(RenderFailure::Kind::ShaderError, e.what(), {e.file(), e.log(), first.text, first.line});
}

}  // namespace

void rethrow_as_render_failure(const std::exception_ptr& error) {
  using Kind = RenderFailure::Kind;
  try {
    std::rethrow_exception(error);
  } catch (const render::DeadlineExceeded& e) {
    throw RenderFailure(Kind::DeadlineExceeded, e.what());
  } catch (const render::RenderAborted& e) {
    throw RenderFailure(Kind::Aborted, e.what());
  } catch (const render::QueueFull& e) {
    throw RenderFailure(Kind::QueueFull, e.what());
  } catch (const gpu::ShaderCompileError& e) {
    throw shader_failure(e);
  } catch (const gpu::GpuReset& e) {
    throw RenderFailure(Kind::GpuReset, e.what());
  } catch (const gpu::GpuError& e) {
    throw RenderFailure(Kind::GpuError, e.what());
  }
}

}  // namespace toond::pipeline
