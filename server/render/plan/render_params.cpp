#include "render/plan/render_params.h"

#include <cmath>

namespace toond::render {

glm::dmat4 SceneObject::matrix() const {
  // Built element by element rather than through glm::rotate so that a zero
  // angle, a unit scale and a zero offset give exactly the identity.
  auto rotation = [](int axis, double deg) {
    glm::dmat4 r(1.0);
    if (deg == 0.0) return r;
    const double a = glm::radians(deg);
    const double c = std::cos(a), s = std::sin(a);
    const int i = (axis + 1) % 3, k = (axis + 2) % 3;  // the plane the axis turns
    r[i][i] = c;
    r[i][k] = s;
    r[k][i] = -s;
    r[k][k] = c;
    return r;
  };
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(translate, 1.0);
  m = m * rotation(2, rotate_deg.z) * rotation(1, rotate_deg.y) * rotation(0, rotate_deg.x);
  glm::dmat4 s(1.0);
  s[0][0] = scale.x;
  s[1][1] = scale.y;
  s[2][2] = scale.z;
  return m * s;
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

glm::vec3 srgb_to_linear(const glm::vec3& c) { return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)}; }

}  // namespace toond::render
