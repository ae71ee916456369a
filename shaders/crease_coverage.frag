#version 430 core
// Crease lines drawn one sample a pixel (crease.frag): each pixel's line
// coverage, the largest any crease line gave it, laid over the image in
// the outline's colour once, so a pixel where two lines meet is darkened
// by the more covering of them, not by both.
layout(binding = 0) uniform sampler2D u_line_coverage;

#include "outline_style.glsl"

layout(location = 0) out vec4 o_color;

void main() {
  float coverage = texelFetch(u_line_coverage, ivec2(gl_FragCoord.xy), 0).r;
  if (coverage <= 0.0) discard;
  o_color = vec4(u_outline_color, coverage);
}
