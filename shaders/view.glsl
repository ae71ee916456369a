// The camera, the same for every pass of a frame; uploaded once per frame
// (ViewBlock in render/frame/uniform_blocks.h mirrors its std140 layout).
layout(std140, binding = 1) uniform FrameView {
  mat4 u_view_projection;
  vec3 u_eye;  // camera position, frame coordinates
  int u_orthographic;
  vec3 u_view_dir;  // unit: the direction the camera looks
  // The size of one pixel at clip w = 1 (a pixel at depth w is w times it;
  // w is 1 everywhere in orthographic views).
  float u_world_per_px_at_w1;
  vec2 u_viewport_px;  // the drawn image's size
};

// Unit vector from a point toward the viewer.
vec3 toward_viewer(vec3 position) {
  return u_orthographic != 0 ? -u_view_dir : normalize(u_eye - position);
}
