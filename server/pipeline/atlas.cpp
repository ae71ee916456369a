#include "pipeline/atlas.h"

#include "render/atlas/sheet_atlas.h"

namespace toond::pipeline {

nlohmann::ordered_json atlas_of(const Request& request, const render::SceneFrame& scene) {
  const render::RenderParams& params = request.params;
  return render::sheet_atlas(*request.layout, params, scene, params.sheet->animate ? "sheet.webp" : "sheet.png");
}

}  // namespace toond::pipeline
