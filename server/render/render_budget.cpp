#include "render/render_budget.h"

#include <string>

#include "request_error.h"

namespace toond::render {

void check_render_budget(const RenderParams& p) {
  const double side_w = static_cast<double>(p.width) * p.supersample;
  const double side_h = static_cast<double>(p.height) * p.supersample;
  if (side_w > kMaxDrawnSide || side_h > kMaxDrawnSide) {
    throw RequestError(422, "too_large",
                       "width/height × supersample exceeds " + std::to_string(kMaxDrawnSide) +
                           " pixels on a side; lower supersample",
                       "/supersample");
  }
  const double samples = side_w * side_h * p.msaa;
  if (samples > kMaxDrawnSamples) {
    throw RequestError(422, "too_large",
                       "width × height × supersample² × msaa = " + std::to_string(static_cast<long long>(samples)) +
                           " samples, more than the " +
                           std::to_string(static_cast<long long>(kMaxDrawnSamples)) +
                           " one render may draw; lower msaa or supersample",
                       p.msaa > 1 ? "/msaa" : "/supersample");
  }
}

}  // namespace toond::render
