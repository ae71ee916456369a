#pragma once
// The texture units the shaders' samplers are bound to by
// layout(binding = N): shaders/material.glsl and toon_shadow.glsl for the
// shading and outline programs, edges.frag and normal_depth_resolve.frag
// for the edge pass's own, downsample.frag for supersampling's,
// crease_coverage.frag for the crease lines' one-sample coverage. The
// renderer binds textures to these and sets no sampler uniforms.
namespace toond::render::texture_unit {

enum Shading : unsigned { kDiffuse = 0, kShadowMap = 1, kNormalMap = 2 };
enum EdgePass : unsigned { kNormalDepth = 0, kCoverage = 1, kPrepassSamples = 0 };
enum DownsamplePass : unsigned { kDrawn = 0 };
enum CreasePass : unsigned { kSceneDepth = 0, kLineCoverage = 0 };

}  // namespace toond::render::texture_unit
