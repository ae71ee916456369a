#version 430 core
// One value per pixel from the multisampled edge prepass: the first covered
// sample stands for the surface and the share of covered samples becomes
// the coverage. A pixel less than half covered counts as background
// (distance 0) but keeps its coverage, which places the silhouette.
layout(binding = 0) uniform sampler2DMS u_samples;  // normal, distance from the eye (0: background)
uniform int u_sample_count;

layout(location = 0) out vec4 o_normal_depth;
layout(location = 1) out float o_coverage;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 first = vec4(0.0);
  int covered = 0;
  for (int s = 0; s < u_sample_count; ++s) {
    vec4 v = texelFetch(u_samples, p, s);
    if (v.w <= 0.0) continue;
    if (covered == 0) first = v;
    ++covered;
  }
  o_normal_depth = 2 * covered < u_sample_count ? vec4(0.0) : first;
  o_coverage = float(covered) / float(u_sample_count);
}
