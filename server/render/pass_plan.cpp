#include "render/pass_plan.h"

#include <algorithm>

namespace toond::render {

const char* pass_name(Pass pass) {
  switch (pass) {
    case Pass::Main: return "main";
    case Pass::HullOutline: return "hull_outline";
    case Pass::Resolve: return "resolve";
    case Pass::Readback: return "readback";
  }
  return "?";
}

bool PassPlan::has(Pass pass) const {
  return std::find(passes.begin(), passes.end(), pass) != passes.end();
}

std::string PassPlan::describe() const {
  std::string out;
  for (Pass p : passes) {
    if (!out.empty()) out += ",";
    out += pass_name(p);
  }
  return out;
}

PassPlan plan_passes(const RenderParams& params, const ModelTraits& model) {
  PassPlan plan;
  plan.samples = params.msaa;
  plan.passes.push_back(Pass::Main);

  switch (params.mode) {
    case ShadingMode::Cel:
      plan.main_defines.push_back("MODE_CEL");
      // Rounding only matters when N·L is quantized.
      plan.main_defines.push_back(params.rounding == Rounding::Floor   ? "ROUND_FLOOR"
                                  : params.rounding == Rounding::Round ? "ROUND_ROUND"
                                                                       : "ROUND_CEIL");
      break;
    case ShadingMode::Phong: plan.main_defines.push_back("MODE_PHONG"); break;
    case ShadingMode::Flat: plan.main_defines.push_back("MODE_FLAT"); break;
  }
  plan.sample_textures = model.has_textures;

  if (params.outline.enabled && params.outline.width_px > 0.0f) {
    plan.passes.push_back(Pass::HullOutline);
  }
  if (plan.samples > 1) plan.passes.push_back(Pass::Resolve);
  plan.passes.push_back(Pass::Readback);
  return plan;
}

}  // namespace toond::render
