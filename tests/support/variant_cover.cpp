#include "support/variant_cover.h"

#include <cstddef>
#include <functional>
#include <set>
#include <tuple>

namespace toond::test {
namespace {

using render::ToonFeature;
using render::ToonVariant;

// One dimension: its choices, each applied to a variant.
using Choice = std::function<void(ToonVariant&)>;
using Dimension = std::vector<Choice>;

Choice features(std::initializer_list<ToonFeature> chosen) {
  // Copied: the initializer list's array ends with the call.
  return [list = std::vector<ToonFeature>(chosen)](ToonVariant& v) {
    for (ToonFeature f : list) v.set(f);
  };
}

Choice nothing() {
  return [](ToonVariant&) {};
}

std::vector<Dimension> dimensions() {
  using F = ToonFeature;
  return {
      {features({F::ModeCel, F::RoundCeil}), features({F::ModeCel, F::RoundFloor}),
       features({F::ModeCel, F::RoundRound}), features({F::ModeCel, F::TwoTone}),
       [](ToonVariant& v) {
         v.set(F::ModeCel).set(F::Ramp);
         v.ramp_count = 3;
       },
       [](ToonVariant& v) {
         v.set(F::ModeCel).set(F::Ramp);
         v.ramp_count = 16;
       },
       features({F::ModePhong}), features({F::ModeFlat})},
      {nothing(), features({F::BandAa})},
      {nothing(), features({F::BaseWhite}), features({F::VertexColor})},
      {nothing(), features({F::HasTexture})},
      {nothing(), features({F::NormalMap})},
      {nothing(), features({F::ShadeColor})},
      {nothing(), features({F::AlphaMask}), features({F::AlphaBlend})},
      {nothing(), features({F::CombineSum})},
      {nothing(), features({F::HasPointLights})},
      {nothing(), features({F::Specular})},
      {nothing(), features({F::Rim}), features({F::Rim, F::RimMaskLit}), features({F::Rim, F::RimMaskShadow})},
      {nothing(), features({F::ContourEven}), features({F::ContourFresnel})},
      {nothing(), features({F::HalftoneDots}), features({F::HalftoneChecker})},
      {nothing(), features({F::LinesOnly})},
      {nothing(), features({F::Shadows}),
       [](ToonVariant& v) {
         v.set(F::Shadows);
         v.shadow_pcf = 2;
       }},
      {[](ToonVariant& v) { v.light_count = -1; }, [](ToonVariant& v) { v.light_count = 0; },
       [](ToonVariant& v) { v.light_count = 1; }, [](ToonVariant& v) { v.light_count = 8; }},
  };
}

// (dimension a, choice of a, dimension b, choice of b), a < b.
using Pair = std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>;

std::set<Pair> every_pair(const std::vector<Dimension>& dims) {
  std::set<Pair> pairs;
  for (std::size_t a = 0; a < dims.size(); ++a)
    for (std::size_t b = a + 1; b < dims.size(); ++b)
      for (std::size_t i = 0; i < dims[a].size(); ++i)
        for (std::size_t j = 0; j < dims[b].size(); ++j) pairs.insert({a, i, b, j});
  return pairs;
}

// Greedy: each new row takes, dimension by dimension, the choice that
// covers the most pairs still missing with the choices made so far.
std::vector<std::size_t> next_row(const std::vector<Dimension>& dims, const std::set<Pair>& missing) {
  std::vector<std::size_t> row;
  for (std::size_t d = 0; d < dims.size(); ++d) {
    std::size_t best = 0;
    std::size_t best_gain = 0;
    for (std::size_t c = 0; c < dims[d].size(); ++c) {
      std::size_t gain = 0;
      for (std::size_t earlier = 0; earlier < d; ++earlier) gain += missing.count({earlier, row[earlier], d, c});
      // Ahead of any pair with a later dimension, prefer a choice that
      // still has pairs to cover.
      for (std::size_t later = d + 1; later < dims.size() && gain == 0; ++later)
        for (std::size_t lc = 0; lc < dims[later].size(); ++lc) gain += missing.count({d, c, later, lc}) ? 1 : 0;
      if (gain > best_gain) {
        best_gain = gain;
        best = c;
      }
    }
    row.push_back(best);
  }
  return row;
}

}  // namespace

std::vector<ToonVariant> pairwise_toon_variants() {
  const std::vector<Dimension> dims = dimensions();
  std::set<Pair> missing = every_pair(dims);
  std::vector<ToonVariant> variants;
  while (!missing.empty()) {
    const std::vector<std::size_t> row = next_row(dims, missing);
    ToonVariant variant;
    for (std::size_t d = 0; d < dims.size(); ++d) {
      dims[d][row[d]](variant);
      for (std::size_t e = d + 1; e < dims.size(); ++e) missing.erase({d, row[d], e, row[e]});
    }
    variants.push_back(variant);
  }
  return variants;
}

}  // namespace toond::test
