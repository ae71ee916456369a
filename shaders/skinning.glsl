// A rigged model's vertices in the request's pose, moved here in the vertex
// stage: each vertex's morph targets, then its joints' blended matrix. The
// model's motions, influences and morph deltas are uploaded once with the
// model; a pose uploads only its joint matrices and its morph weights
// (render/frame/gpu_skin.h lays the blocks out). An object that is not posed
// (u_skinned 0, object.glsl) draws its attributes as they are.
// Include after attributes.glsl and object.glsl.

// Per vertex (gl_VertexID: draws use no base vertex), its motion.
layout(std430, binding = 0) readonly buffer SkinVertexMotions { uint s_vertex_motion[]; };
// Per motion: first influence, influence count, morph set + 1 (0: none),
// the vertex's index in that set.
layout(std430, binding = 1) readonly buffer SkinMotions { uvec4 s_motion[]; };
// Per influence: the joint (into s_joint), the weight's bits.
layout(std430, binding = 2) readonly buffer SkinInfluences { uvec2 s_influence[]; };
// Per morph target and vertex of a set: position, normal and tangent deltas.
layout(std430, binding = 3) readonly buffer SkinMorphDeltas { vec4 s_morph_delta[]; };
// The pose: each joint's matrix, rest mesh space to posed mesh space.
layout(std430, binding = 4) readonly buffer PoseJoints { mat4 s_joint[]; };
// The pose's morphs: per set (first delta, vertices, first weighted target,
// weighted targets), then the weighted targets (target, weight's bits).
// Only targets of nonzero weight are listed: a face with fifty targets
// mostly at rest costs only the few that move.
layout(std430, binding = 5) readonly buffer PoseMorphs { uvec4 s_pose_morph[]; };

struct PosedVertex {
  vec3 position;
  vec3 normal;
  vec3 outline_offset;
  vec4 tangent;
};

vec3 skin_unit_or(vec3 v, vec3 fallback) {
  float len = length(v);
  return len > 1e-20 && !isinf(len) ? v / len : fallback;
}

void add_morph_targets(uint set_plus_one, uint vertex, inout vec3 position, inout vec3 normal, inout vec3 tangent) {
  if (set_plus_one == 0u) return;
  uvec4 set = s_pose_morph[set_plus_one - 1u];
  for (uint k = set.z; k < set.z + set.w; ++k) {
    uvec4 target = s_pose_morph[k];
    float weight = uintBitsToFloat(target.y);
    uint at = 3u * (set.x + target.x * set.y + vertex);
    position += weight * s_morph_delta[at].xyz;
    normal += weight * s_morph_delta[at + 1u].xyz;
    tangent += weight * s_morph_delta[at + 2u].xyz;
  }
}

// The rest attributes moved into the pose. Normals go through the blend's
// cofactor (det · inverse-transpose, undivided: a joint scaled to nothing
// gives a zero normal, which falls back to the rest one, not NaN); the
// outline offset turns with them and keeps its length (its mitre); the
// tangent follows the blend and is made square to the posed normal again.
PosedVertex posed_vertex() {
  PosedVertex v = PosedVertex(a_position, a_normal, a_outline_offset, a_tangent);
  if (u_skinned == 0) return v;
  uvec4 motion = s_motion[s_vertex_motion[gl_VertexID]];
  vec3 normal = a_normal;
  vec3 tangent = a_tangent.xyz;
  add_morph_targets(motion.z, motion.w, v.position, normal, tangent);
  mat4 blend = mat4(0.0);
  for (uint k = motion.x; k < motion.x + motion.y; ++k) {
    uvec2 influence = s_influence[k];
    blend += uintBitsToFloat(influence.y) * s_joint[influence.x];
  }
  mat3 turn = mat3(blend);
  mat3 cofactor = mat3(cross(turn[1], turn[2]), cross(turn[2], turn[0]), cross(turn[0], turn[1]));
  v.position = (blend * vec4(v.position, 1.0)).xyz;
  v.normal = skin_unit_or(cofactor * normal, a_normal);
  v.outline_offset = skin_unit_or(cofactor * a_outline_offset, v.normal) * length(a_outline_offset);
  vec3 along = turn * tangent;
  v.tangent = vec4(skin_unit_or(along - v.normal * dot(v.normal, along), a_tangent.xyz), a_tangent.w);
  return v;
}
