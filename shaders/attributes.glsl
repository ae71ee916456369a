// Every vertex stage's inputs, at the locations render/frame/vertex_attribute.h
// gives GpuModel's buffers. A stage reads what it needs; the rest stay
// inactive.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;
layout(location = 3) in vec3 a_outline_offset;  // outline_normals: averaged over a position, mitred
layout(location = 4) in vec4 a_tangent;         // xyz, w = bitangent handedness
layout(location = 5) in vec3 a_color;           // sRGB-encoded vertex colour
