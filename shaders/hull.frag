#version 430 core
// Outline colour: the stencil test leaves only the ring outside the model.
// Variants: fixed colour (default), OUTLINE_MATERIAL (the material colour
// darkened), OUTLINE_TEXTURE (the texture under the line, inverted and
// darkened); ALPHA_MASK (no line where a masked material is cut out).
in vec2 v_texcoord;

#include "material.glsl"
#include "outline_style.glsl"

#ifdef LINE_SEGMENT
// Wireframe lines: the edge's ends in window coordinates, and half the
// line's width. The quads that carry a line reach past its ends so lines
// join; only the points within the half width of the segment itself are
// drawn (round ends), so no corner of a quad pokes out past the ring.
// Without it the alpha written is 1.
flat in vec2 v_segment_a;
flat in vec2 v_segment_b;

#include "line_segment.glsl"
#endif

layout(location = 0) out vec4 o_color;

void main() {
#ifdef ALPHA_MASK
  if (masked_out(v_texcoord)) discard;
#endif
#ifdef LINE_SEGMENT
  // How much of the pixel the line covers across its edge; with
  // multisampling it becomes the samples written (alpha to coverage), so
  // the line's edge is antialiased like a triangle's.
  float coverage = clamp(u_width - distance_to_segment(gl_FragCoord.xy, v_segment_a, v_segment_b) + 0.5, 0.0, 1.0);
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
