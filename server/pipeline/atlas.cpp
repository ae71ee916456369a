#include "pipeline/atlas.h"

#include "render/atlas/sheet_atlas.h"

namespace toond::pipeline {

nlohmann::ordered_json atlas_of(const Request& request, const std::vector<render::FramePlan>& plans) {
  const render::RenderParams& params = request.params;
  return render::sheet_atlas(*request.layout, params, plans, params.sheet->animate ? "sheet.webp" : "sheet.png");
}

}  // namespace toond::pipeline
