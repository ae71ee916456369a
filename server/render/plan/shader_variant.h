#pragma once
// Shader variants as types: a set of features (each a #define of the
// shader) plus the counts some features carry. The plan and the passes
// build and test these; only ProgramCache sees their #define strings.
// Every program variant a plan can draw with is one of these types, so a
// test can build them all (ShaderVariants).
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
  LinesOnly,
  AlphaBlend,
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

// A set of on/off features of a shader with no counts: `Feature` is an
// enum ending in Count, and define_name(Feature) names its #defines.
template <class Feature>
struct FeatureSet {
  static constexpr std::size_t kCount = static_cast<std::size_t>(Feature::Count);
  std::bitset<kCount> features;

  bool has(Feature f) const { return features.test(static_cast<std::size_t>(f)); }
  FeatureSet& set(Feature f, bool on = true) {
    features.set(static_cast<std::size_t>(f), on);
    return *this;
  }
  std::vector<std::string> defines() const {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < kCount; ++i) {
      if (features.test(i)) out.emplace_back(define_name(static_cast<Feature>(i)));
    }
    return out;
  }
  // Every set of these features, for tests that compile them all.
  static std::vector<FeatureSet> all() {
    std::vector<FeatureSet> out;
    for (unsigned long bits = 0; bits < (1ul << kCount); ++bits) out.push_back(FeatureSet{std::bitset<kCount>(bits)});
    return out;
  }
  bool operator==(const FeatureSet&) const = default;
};

// hull.frag's features (the hull pass and the wireframe share it).
enum class OutlineFeature : std::size_t { Material, Texture, LineSegment, AlphaMask, Count };
const char* define_name(OutlineFeature feature);

struct OutlineVariant : FeatureSet<OutlineFeature> {
  // Whether the colour comes from each material (not one fixed colour).
  bool per_material() const { return has(OutlineFeature::Material) || has(OutlineFeature::Texture); }
};

// The passes that write only depth or normals (shadow.frag,
// normal_depth.frag): the alpha test of masked materials.
enum class DepthFeature : std::size_t { AlphaMask, Count };
const char* define_name(DepthFeature feature);
using DepthVariant = FeatureSet<DepthFeature>;

// edges.frag's: creases alone, when another pass draws the silhouette.
enum class EdgeFeature : std::size_t { CreasesOnly, Count };
const char* define_name(EdgeFeature feature);
using EdgeVariant = FeatureSet<EdgeFeature>;

// crease.frag's: the target has several samples a pixel, which each line
// writes by the samples it covers (else it writes each pixel's coverage).
// crease.geom's: each line is drawn as a wide GL line (one primitive),
// else as a quad (two triangles), where the driver's lines are too narrow.
enum class CreaseFeature : std::size_t { SampleMask, WideLines, Count };
const char* define_name(CreaseFeature feature);
using CreaseVariant = FeatureSet<CreaseFeature>;

// downsample.frag's: the drawn colour is premultiplied (the lines layer).
enum class DownsampleFeature : std::size_t { Premultiplied, Count };
const char* define_name(DownsampleFeature feature);
using DownsampleVariant = FeatureSet<DownsampleFeature>;

// layer.frag's: which data layer it writes (one of the first three), and
// the alpha test of masked materials.
enum class LayerFeature : std::size_t { Depth, Normal, Id, AlphaMask, Count };
const char* define_name(LayerFeature feature);
using LayerVariant = FeatureSet<LayerFeature>;

}  // namespace toond::render
