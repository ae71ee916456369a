#pragma once
// Shader variants as types: a set of features (each a #define of the
// shader) plus the counts some features carry. The plan and the passes
// build and test these; only ProgramCache sees their #define strings.
#include <bitset>
#include <cstddef>
#include <string>
#include <vector>

namespace toond::render {

// toon.frag's features; the comment at its top says what each does.
enum class ToonFeature : std::size_t {
  ModeCel,
  ModePhong,
  ModeFlat,
  RoundCeil,
  RoundFloor,
  RoundRound,
  TwoTone,
  Ramp,
  BandAa,
  BaseWhite,
  HasTexture,
  VertexColor,
  NormalMap,
  ShadeColor,
  CombineSum,
  HasPointLights,
  Specular,
  Rim,
  RimMaskLit,
  RimMaskShadow,
  ContourEven,
  ContourFresnel,
  HalftoneDots,
  HalftoneChecker,
  Shadows,
  AlphaMask,
  Count
};
const char* define_name(ToonFeature feature);

struct ToonVariant {
  std::bitset<static_cast<std::size_t>(ToonFeature::Count)> features;
  int light_count = -1;  // LIGHT_COUNT (lit modes), -1: not set
  int ramp_count = 0;    // RAMP_COUNT with Ramp
  int shadow_pcf = 0;    // SHADOW_PCF with Shadows: (2n+1)² taps; 0: one tap

  bool has(ToonFeature f) const { return features.test(static_cast<std::size_t>(f)); }
  ToonVariant& set(ToonFeature f, bool on = true) {
    features.set(static_cast<std::size_t>(f), on);
    return *this;
  }
  // The shading mode, replaced (an unlit material is drawn flat).
  ToonVariant& set_mode(ToonFeature mode);
  std::vector<std::string> defines() const;
  bool operator==(const ToonVariant&) const = default;
};

// hull.frag's features (the hull pass and the wireframe share it).
enum class OutlineFeature : std::size_t { Material, Texture, LineSegment, AlphaMask, Count };
const char* define_name(OutlineFeature feature);

struct OutlineVariant {
  std::bitset<static_cast<std::size_t>(OutlineFeature::Count)> features;

  bool has(OutlineFeature f) const { return features.test(static_cast<std::size_t>(f)); }
  OutlineVariant& set(OutlineFeature f, bool on = true) {
    features.set(static_cast<std::size_t>(f), on);
    return *this;
  }
  // Whether the colour comes from each material (not one fixed colour).
  bool per_material() const { return has(OutlineFeature::Material) || has(OutlineFeature::Texture); }
  std::vector<std::string> defines() const;
  bool operator==(const OutlineVariant&) const = default;
};

}  // namespace toond::render
