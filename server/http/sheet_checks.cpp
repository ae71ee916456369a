#include "http/sheet_checks.h"

#include <string>

#include "request_error.h"

namespace toond::http {

void check_sheet_params(const render::RenderParams& params) {
  if (!params.sheet || !params.sheet->pixel_art) return;
  const int scale = params.sheet->pixel_art->scale;
  if (params.width % scale != 0 || params.height % scale != 0) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/pixel_art/scale: " + std::to_string(scale) + " must divide the tile size " +
                           std::to_string(params.width) + "×" + std::to_string(params.height) +
                           " (width and height) so every tile is whole art pixels",
                       "/sheet/pixel_art/scale");
  }
}

}  // namespace toond::http
