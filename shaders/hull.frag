#version 430 core
// Outline colour: the stencil test leaves only the ring outside the model.
// Variants: fixed colour (default), OUTLINE_MATERIAL (the material colour
// darkened), OUTLINE_TEXTURE (the texture under the line, inverted and
// darkened); ALPHA_MASK (no line where a masked material is cut out).
in vec2 v_texcoord;

uniform vec3 u_outline_color;  // linear
#if defined(OUTLINE_MATERIAL) || defined(OUTLINE_TEXTURE)
uniform vec3 u_base_color;
uniform float u_darken;
#endif
#ifdef OUTLINE_TEXTURE
uniform int u_has_texture;
uniform sampler2D u_diffuse_map;
#endif

#ifdef LINE_SEGMENT
// Wireframe lines: the edge's ends in window coordinates, and half the
// line's width. The quads that carry a line reach past its ends so lines
// join; only the points within the half width of the segment itself are
// drawn (round ends), so no corner of a quad pokes out past the ring.
// Without it the alpha written is 1.
flat in vec2 v_segment_a;
flat in vec2 v_segment_b;
uniform float u_half_line_px;

float distance_to_segment(vec2 p, vec2 a, vec2 b) {
  vec2 ab = b - a;
  float t = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
  return length(p - (a + t * ab));
}
#endif

layout(location = 0) out vec4 o_color;

#ifdef ALPHA_MASK
// Masked materials (glTF alphaMode MASK): the same alpha test as the main
// pass, so nothing lands where it drew nothing (render/passes/alpha_mask.h
// sets these; an opaque material's cutoff is one nothing fails).
uniform sampler2D u_mask_map;
uniform int u_mask_has_texture;
uniform float u_mask_opacity;
uniform float u_mask_cutoff;

bool masked_out(vec2 uv) {
  float alpha = u_mask_opacity * (u_mask_has_texture != 0 ? texture(u_mask_map, uv).a : 1.0);
  return alpha < u_mask_cutoff;
}
#endif

void main() {
#ifdef ALPHA_MASK
  if (masked_out(v_texcoord)) discard;
#endif
#ifdef LINE_SEGMENT
  // How much of the pixel the line covers across its edge; with
  // multisampling it becomes the samples written (alpha to coverage), so
  // the line's edge is antialiased like a triangle's.
  float coverage = clamp(u_half_line_px - distance_to_segment(gl_FragCoord.xy, v_segment_a, v_segment_b) + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
#else
  const float coverage = 1.0;
#endif
#if defined(OUTLINE_TEXTURE)
  vec3 source = u_has_texture != 0 ? vec3(1.0) - texture(u_diffuse_map, v_texcoord).rgb * u_base_color
                                   : u_base_color;
  o_color = vec4(source * (1.0 - u_darken), coverage);
#elif defined(OUTLINE_MATERIAL)
  o_color = vec4(u_base_color * (1.0 - u_darken), coverage);
#else
  o_color = vec4(u_outline_color, coverage);
#endif
}
