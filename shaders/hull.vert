#version 430 core
// Inverted-hull outline. Each vertex moves outward along its outline normal,
// the normal averaged over every vertex at the same position: with the
// shading normals, hard edges (a cube's corners) split into separate
// vertices that move apart and tear gaps in the hull (the well-known
// problem, e.g. three.js issue 19096).
//
// The offset is made in screen space, `u_width_px` pixels along the
// projected normal, so the line is equally wide at any distance.
layout(location = 0) in vec3 a_position;
layout(location = 3) in vec3 a_outline_normal;

uniform mat4 u_view_projection;
uniform vec2 u_viewport;  // pixels
uniform float u_width_px;

void main() {
  vec4 clip = u_view_projection * vec4(a_position, 1.0);
  vec4 clip_dir = u_view_projection * vec4(a_outline_normal, 0.0);
  // Derivative of the NDC position along the normal, in pixels.
  vec2 screen_dir = (clip_dir.xy * clip.w - clip.xy * clip_dir.w) * (0.5 * u_viewport);
  float len = length(screen_dir);
  if (len > 1e-30 && clip.w > 0.0) {
    vec2 offset_ndc = (screen_dir / len) * u_width_px * 2.0 / u_viewport;
    clip.xy += offset_ndc * clip.w;
  }
  gl_Position = clip;
}
