// Lights in view space turn with the camera (render/light_space): at the
// camera's yaw 0, pitch 0 they are the model-space lights; turned half way
// round, a light from the front lights the back. The wire's default: a
// sheet's lights are in view space unless they say otherwise.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "presets.h"
#include "render/plan/camera.h"
#include "render/plan/light_space.h"
#include "request_error.h"

namespace toond::render {
namespace {

using nlohmann::json;

void expect_same_vector(const glm::dvec3& got, const glm::dvec3& want, const char* what) {
  EXPECT_NEAR(got.x, want.x, 1e-12) << what;
  EXPECT_NEAR(got.y, want.y, 1e-12) << what;
  EXPECT_NEAR(got.z, want.z, 1e-12) << what;
}

CameraParams orbit_camera_at(double yaw, double pitch) {
  CameraParams camera;
  camera.yaw_deg = yaw;
  camera.pitch_deg = pitch;
  return camera;
}

TEST(LightSpace, AtYawZeroPitchZeroTheViewIsTheModel) {
  const CameraParams front = orbit_camera_at(0, 0);
  expect_same_vector(view_to_scene(front, {-0.4, -0.5, -1}), {-0.4, -0.5, -1}, "the default light");
}

// Whatever the view, a view-space vector seen through that view's own
// matrix is the vector given: x right, y up, z toward the viewer.
TEST(LightSpace, AViewSpaceVectorIsWhatTheCameraSeesItAs) {
  const std::pair<double, double> views[] = {{180, 0}, {90, 30}, {-135, -60}, {45, 35.264}};
  for (const auto& [yaw, pitch] : views) {
    const CameraParams camera = orbit_camera_at(yaw, pitch);
    const glm::dvec3 eye = toward_eye(yaw, pitch) * 5.0;
    const glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    const glm::dvec3 given(-0.4, -0.5, -1.0);
    const glm::dvec3 seen = glm::dmat3(view) * view_to_scene(camera, given);
    expect_same_vector(seen, given, "through the view matrix");
  }
}

TEST(LightSpace, ViewLightsTurnWithTheCameraModelLightsStay) {
  Light front_light;
  front_light.direction = {0, 0, -1};  // travels away from the viewer: lights what the camera sees
  front_light.space = LightSpace::View;
  Light point;
  point.kind = LightKind::Point;
  point.position = {0, 0, 2};  // two units toward the viewer from the orbit's centre
  point.space = LightSpace::View;
  Light fixed = front_light;
  fixed.space = LightSpace::Model;
  const glm::dvec3 centre(10, 1, -3);
  const std::vector<Light> placed = lights_in_scene({front_light, point, fixed}, orbit_camera_at(180, 0), centre);
  ASSERT_EQ(placed.size(), 3u);
  expect_same_vector(placed[0].direction, {0, 0, 1}, "seen from behind, it lights the back");
  expect_same_vector(placed[1].position, centre + glm::dvec3(0, 0, -2), "the point light follows the eye round");
  expect_same_vector(placed[2].direction, {0, 0, -1}, "a model-space light stays");
  for (const Light& l : placed) EXPECT_EQ(l.space, LightSpace::Model);
}

RenderParams light_params_of(const json& request) {
  const json expanded = proto::Presets::builtin().expand(request);
  return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(expanded));
}

TEST(LightSpace, ASheetsLightsAreInViewSpaceUnlessTheySayOtherwise) {
  EXPECT_EQ(light_params_of(json::object()).lights.at(0).space, LightSpace::Model) << "a single image";
  EXPECT_EQ(light_params_of({{"sheet", {{"frames", 4}}}}).lights.at(0).space, LightSpace::View) << "a sheet";
  const json lights = {{{"type", "directional"}, {"direction", {0, -1, 0}}, {"space", "model"}},
                       {{"type", "point"}, {"position", {1, 2, 3}}}};
  const RenderParams sheet = light_params_of({{"lights", lights}, {"sheet", {{"frames", 4}}}});
  EXPECT_EQ(sheet.lights.at(0).space, LightSpace::Model) << "as given";
  EXPECT_EQ(sheet.lights.at(1).space, LightSpace::View) << "absent, in a sheet";
  json single_view = {{"lights", {{{"type", "directional"}, {"direction", {0, -1, 0}}, {"space", "view"}}}}};
  EXPECT_EQ(light_params_of(single_view).lights.at(0).space, LightSpace::View);
  single_view["lights"][0]["space"] = "world";
  try {
    proto::ParamSchema::render_params().validate(single_view);
    ADD_FAILURE() << "space world was accepted";
  } catch (const RequestError& e) {
    EXPECT_EQ(e.path(), "/lights/0/space");
    EXPECT_EQ(e.status(), 400);
  }
}

}  // namespace
}  // namespace toond::render
