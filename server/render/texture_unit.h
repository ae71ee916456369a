#pragma once
// The texture units the shaders' samplers are bound to by
// layout(binding = N): shaders/material.glsl and toon_shadow.glsl for the
// shading programs, edges.frag and normal_depth_resolve.frag for the edge
// pass's own. The renderer binds textures to these and sets no sampler
// uniforms.
namespace toond::render::texture_unit {

// Shading and outline programs.
inline constexpr unsigned kDiffuse = 0;
inline constexpr unsigned kShadowMap = 1;
inline constexpr unsigned kNormalMap = 2;
// The edge pass and the prepass's resolve.
inline constexpr unsigned kNormalDepth = 0;
inline constexpr unsigned kCoverage = 1;
inline constexpr unsigned kPrepassSamples = 0;

}  // namespace toond::render::texture_unit
