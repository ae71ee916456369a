#version 430 core
// Supersampling's filter: each output pixel is the mean of the k × k block
// of drawn pixels it covers. The mean is taken on linear light (the source
// texture is sRGB, decoded on fetch; the target encodes on write), so a
// half-covered edge is half as bright, as the MSAA resolve makes it. Colour
// is weighted by alpha, so transparent background does not darken an edge.
// PREMULTIPLIED (the lines layer): the drawn colour is already multiplied
// by its alpha, so the sums divide out to straight colour directly.
layout(binding = 0) uniform sampler2D u_drawn;
uniform int u_factor;

layout(location = 0) out vec4 o_color;

void main() {
  const ivec2 corner = ivec2(gl_FragCoord.xy) * u_factor;
  vec3 colour = vec3(0.0);
  float alpha = 0.0;
  for (int dy = 0; dy < u_factor; ++dy) {
    for (int dx = 0; dx < u_factor; ++dx) {
      vec4 drawn = texelFetch(u_drawn, corner + ivec2(dx, dy), 0);
#ifdef PREMULTIPLIED
      colour += drawn.rgb;
#else
      colour += drawn.rgb * drawn.a;
#endif
      alpha += drawn.a;
    }
  }
  o_color = vec4(alpha > 0.0 ? colour / alpha : vec3(0.0), alpha / float(u_factor * u_factor));
}
