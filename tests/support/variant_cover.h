#pragma once
// toon.frag variants that together hold every pair of feature choices:
// each dimension (the shading mode and its band options, the base colour,
// each optional effect, shadows and their filter, the light and ramp
// counts) meets every value of every other in at least one variant. The
// plan's variants are drawn from the same choices, so a feature that fails
// to compile beside another shows up here; all of them together would be
// hundreds of thousands.
#include <vector>

#include "render/plan/shader_variant.h"

namespace toond::test {

std::vector<render::ToonVariant> pairwise_toon_variants();

}  // namespace toond::test
