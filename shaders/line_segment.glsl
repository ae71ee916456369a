// Distance in window pixels from a point to the segment a–b: what the line
// shaders (the wireframe's hull.frag, crease.frag) cover, so a line ends in
// a round cap and two lines meeting at a point join round.
float distance_to_segment(vec2 p, vec2 a, vec2 b) {
  vec2 ab = b - a;
  float t = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
  return length(p - (a + t * ab));
}
