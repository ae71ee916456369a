#version 430 core
// Outline colour: the stencil test leaves only the ring outside the model.
uniform vec3 u_outline_color;  // linear
layout(location = 0) out vec4 o_color;

void main() { o_color = vec4(u_outline_color, 1.0); }
