// The window depth drawn before the crease lines, every sample of it: the
// target's own depth (RenderTarget::depth_texture), which the lines read
// while they draw into a framebuffer without it; a multisample texture
// when the target is multisampled (SAMPLE_MASK), else one sample a pixel.
#ifdef SAMPLE_MASK
layout(binding = 0) uniform sampler2DMS u_scene_depth;
#else
layout(binding = 0) uniform sampler2D u_scene_depth;
#endif

// The depth drawn at sample `k` of the pixel holding `p` (clamped to the
// image); sample 0 where the target has one.
float scene_depth(vec2 p, int k) {
#ifdef SAMPLE_MASK
  ivec2 last = textureSize(u_scene_depth) - 1;
  return texelFetch(u_scene_depth, clamp(ivec2(floor(p)), ivec2(0), last), k).r;
#else
  ivec2 last = textureSize(u_scene_depth, 0) - 1;
  return texelFetch(u_scene_depth, clamp(ivec2(floor(p)), ivec2(0), last), 0).r;
#endif
}
