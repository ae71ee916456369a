// Where an object of the frame stands: bound per object from the frame's
// uniform buffer (ObjectBlock in render/frame/uniform_blocks.h).
layout(std140, binding = 2) uniform ObjectPlacement {
  mat4 u_model;          // mesh → scene (frame) coordinates
  mat3 u_normal_matrix;  // inverse-transpose of u_model's 3×3
  int u_skinned;         // 1: drawn in a pose (skinning.glsl)
};
