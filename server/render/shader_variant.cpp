#include "render/shader_variant.h"

namespace toond::render {

const char* define_name(ToonFeature feature) {
  switch (feature) {
    case ToonFeature::ModeCel: return "MODE_CEL";
    case ToonFeature::ModePhong: return "MODE_PHONG";
    case ToonFeature::ModeFlat: return "MODE_FLAT";
    case ToonFeature::RoundCeil: return "ROUND_CEIL";
    case ToonFeature::RoundFloor: return "ROUND_FLOOR";
    case ToonFeature::RoundRound: return "ROUND_ROUND";
    case ToonFeature::TwoTone: return "TWO_TONE";
    case ToonFeature::Ramp: return "RAMP";
    case ToonFeature::BandAa: return "BAND_AA";
    case ToonFeature::BaseWhite: return "BASE_WHITE";
    case ToonFeature::HasTexture: return "HAS_TEXTURE";
    case ToonFeature::VertexColor: return "VERTEX_COLOR";
    case ToonFeature::NormalMap: return "NORMAL_MAP";
    case ToonFeature::ShadeColor: return "SHADE_COLOR";
    case ToonFeature::CombineSum: return "COMBINE_SUM";
    case ToonFeature::HasPointLights: return "HAS_POINT_LIGHTS";
    case ToonFeature::Specular: return "SPECULAR";
    case ToonFeature::Rim: return "RIM";
    case ToonFeature::RimMaskLit: return "RIM_MASK_LIT";
    case ToonFeature::RimMaskShadow: return "RIM_MASK_SHADOW";
    case ToonFeature::ContourEven: return "CONTOUR_EVEN";
    case ToonFeature::ContourFresnel: return "CONTOUR_FRESNEL";
    case ToonFeature::HalftoneDots: return "HALFTONE_DOTS";
    case ToonFeature::HalftoneChecker: return "HALFTONE_CHECKER";
    case ToonFeature::Shadows: return "SHADOWS";
    case ToonFeature::AlphaMask: return "ALPHA_MASK";
    case ToonFeature::Count: break;
  }
  return "?";
}

const char* define_name(OutlineFeature feature) {
  switch (feature) {
    case OutlineFeature::Material: return "OUTLINE_MATERIAL";
    case OutlineFeature::Texture: return "OUTLINE_TEXTURE";
    case OutlineFeature::LineSegment: return "LINE_SEGMENT";
    case OutlineFeature::AlphaMask: return "ALPHA_MASK";
    case OutlineFeature::Count: break;
  }
  return "?";
}

ToonVariant& ToonVariant::set_mode(ToonFeature mode) {
  set(ToonFeature::ModeCel, false);
  set(ToonFeature::ModePhong, false);
  set(ToonFeature::ModeFlat, false);
  return set(mode);
}

std::vector<std::string> ToonVariant::defines() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < features.size(); ++i) {
    if (features.test(i)) out.emplace_back(define_name(static_cast<ToonFeature>(i)));
  }
  if (light_count >= 0) out.push_back("LIGHT_COUNT " + std::to_string(light_count));
  if (has(ToonFeature::Ramp)) out.push_back("RAMP_COUNT " + std::to_string(ramp_count));
  if (has(ToonFeature::Shadows) && shadow_pcf > 0) out.push_back("SHADOW_PCF " + std::to_string(shadow_pcf));
  return out;
}

std::vector<std::string> OutlineVariant::defines() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < features.size(); ++i) {
    if (features.test(i)) out.emplace_back(define_name(static_cast<OutlineFeature>(i)));
  }
  return out;
}

}  // namespace toond::render
