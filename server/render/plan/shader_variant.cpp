#include "render/plan/shader_variant.h"

#include <array>

namespace toond::render {

namespace {

// Each feature's #define, in the order of its enum. An array sized by the
// enum's Count but given fewer names fills up with nulls: all_named keeps
// the two in step.
constexpr std::array<const char*, static_cast<std::size_t>(ToonFeature::Count)> kToonDefines = {
    "MODE_CEL",         "MODE_PHONG",      "MODE_FLAT",     "ROUND_CEIL",       "ROUND_FLOOR",
    "ROUND_ROUND",      "TWO_TONE",        "RAMP",          "BAND_AA",          "BASE_WHITE",
    "HAS_TEXTURE",      "VERTEX_COLOR",    "NORMAL_MAP",    "SHADE_COLOR",      "COMBINE_SUM",
    "HAS_POINT_LIGHTS", "SPECULAR",        "RIM",           "RIM_MASK_LIT",     "RIM_MASK_SHADOW",
    "CONTOUR_EVEN",     "CONTOUR_FRESNEL", "HALFTONE_DOTS", "HALFTONE_CHECKER", "SHADOWS",
    "ALPHA_MASK",       "LINES_ONLY",      "ALPHA_BLEND"};
constexpr std::array<const char*, static_cast<std::size_t>(OutlineFeature::Count)> kOutlineDefines = {
    "OUTLINE_MATERIAL", "OUTLINE_TEXTURE", "LINE_SEGMENT", "ALPHA_MASK"};
constexpr std::array<const char*, static_cast<std::size_t>(DepthFeature::Count)> kDepthDefines = {"ALPHA_MASK"};
constexpr std::array<const char*, static_cast<std::size_t>(EdgeFeature::Count)> kEdgeDefines = {"CREASES_ONLY"};
constexpr std::array<const char*, static_cast<std::size_t>(CreaseFeature::Count)> kCreaseDefines = {"SAMPLE_MASK",
                                                                                                    "WIDE_LINES"};
constexpr std::array<const char*, static_cast<std::size_t>(DownsampleFeature::Count)> kDownsampleDefines = {
    "PREMULTIPLIED"};
constexpr std::array<const char*, static_cast<std::size_t>(LayerFeature::Count)> kLayerDefines = {
    "LAYER_DEPTH", "LAYER_NORMAL", "LAYER_ID", "ALPHA_MASK"};

template <std::size_t N>
constexpr bool all_named(const std::array<const char*, N>& names) {
  for (const char* name : names) {
    if (name == nullptr) return false;
  }
  return true;
}
static_assert(all_named(kToonDefines) && all_named(kOutlineDefines) && all_named(kDepthDefines) &&
              all_named(kEdgeDefines) && all_named(kCreaseDefines) && all_named(kDownsampleDefines) &&
              all_named(kLayerDefines));

template <class Feature, std::size_t N>
const char* name_in(const std::array<const char*, N>& names, Feature feature) {
  const auto i = static_cast<std::size_t>(feature);
  return i < N ? names[i] : "?";
}

}  // namespace

const char* define_name(ToonFeature feature) { return name_in(kToonDefines, feature); }
const char* define_name(OutlineFeature feature) { return name_in(kOutlineDefines, feature); }
const char* define_name(DepthFeature feature) { return name_in(kDepthDefines, feature); }
const char* define_name(EdgeFeature feature) { return name_in(kEdgeDefines, feature); }
const char* define_name(CreaseFeature feature) { return name_in(kCreaseDefines, feature); }
const char* define_name(DownsampleFeature feature) { return name_in(kDownsampleDefines, feature); }
const char* define_name(LayerFeature feature) { return name_in(kLayerDefines, feature); }

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

}  // namespace toond::render
