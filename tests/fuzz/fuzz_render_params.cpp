// libFuzzer target: a POST /render body through what the daemon does with
// it before the render thread (size and depth limits, the schema, presets,
// defaults, RenderParams, the render budget). A RequestError is a 4xx
// answer and fine; any other exception would be a 500, and is a finding.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "http/request_limits.h"
#include "param_schema.h"
#include "pipeline/budget.h"
#include "pipeline/frames.h"
#include "pipeline/render_params_wire.h"
#include "presets.h"
#include "render/plan/render_params.h"
#include "request_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  toond::http::RequestLimits limits;
  limits.max_json_bytes = 64 * 1024;
  try {
    const nlohmann::json request = toond::http::parse_limited_json(text, limits, "the request body");
    toond::http::check_request_counts(request, limits);
    const auto& schema = toond::proto::ParamSchema::render_params();
    schema.validate(request);
    const auto params = toond::pipeline::render_params_from_wire(
        schema.validate_and_complete(toond::proto::Presets::builtin().expand(request)));
    toond::pipeline::check_render_budget(params, toond::pipeline::layout_of(params), limits.render);
  } catch (const toond::RequestError&) {
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_render_params: unexpected exception (a 500 in the daemon): %s\n", e.what());
    std::abort();
  }
  return 0;
}
