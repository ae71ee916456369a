#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "gpu/egl_context.h"
#include "gpu/gpu_error.h"
#include "image/downsample.h"
#include "render/camera.h"
#include "render/pass_timer.h"
#include "render/lod_choice.h"
#include "render/outline_width.h"
#include "render/shadow_fit.h"

namespace toond::render {
namespace {

// Samples per pixel of the edge prepass when it places silhouettes: a
// quarter pixel of coverage per sample, which the analytic oracle measures
// as widths within 0.4 px.
constexpr int kSilhouetteSamples = 4;

void check_gl(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw gpu::GpuError(std::string("GL error 0x") + std::to_string(error) + " in " + where);
  }
}

// A square ground plane just under the model's lowest point (a hair lower,
// so a flat-bottomed model does not z-fight with it), facing up; its texture
// coordinates run over `repeat` tiles per side.
scene::Model make_floor(const scene::Bounds& bounds, float size, float repeat,
                        const std::shared_ptr<const scene::Texture>& image) {
  const float half = bounds.radius() * size;
  const glm::vec3 c = bounds.centre();
  const float y = bounds.min.y - bounds.radius() * 1e-3f;
  scene::Model floor;
  scene::Mesh& m = floor.mesh;
  m.positions = {{c.x - half, y, c.z - half}, {c.x + half, y, c.z - half}, {c.x + half, y, c.z + half},
                 {c.x - half, y, c.z + half}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.outline_normals.assign(4, glm::vec3(0, 1, 0));
  m.texcoords = {{0, 0}, {repeat, 0}, {repeat, repeat}, {0, repeat}};
  m.indices = {0, 2, 1, 0, 3, 2};
  m.submeshes = {{0, 6, 0}};
  m.bounds = {m.positions[0], m.positions[2]};
  floor.materials.push_back({});
  if (image) {
    floor.textures.push_back(*image);
    floor.materials[0].diffuse_texture = 0;
  }
  return floor;
}

// Per object, the coarsest level whose error, at the object's nearest
// distance from the camera, stays within the pixel budget. Scale in the
// object's transform scales its error along.
std::vector<LodUse> choose_levels(const std::vector<RenderObject>& objects, const SceneFrame& frame,
                                  const RenderParams& params) {
  const CameraSetup camera =
      fit_camera(params.camera, frame.bounds, static_cast<double>(params.width) / params.height, frame.outline);
  const bool ortho = params.camera.projection == Projection::Orthographic;
  std::vector<LodUse> uses;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const GpuModel& model = objects[i].model;
    const glm::dmat4& m = frame.matrices[i];
    const double scale =
        std::max({glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])), glm::length(glm::dvec3(m[2]))});
    const glm::dvec3 centre = glm::dvec3(m * glm::dvec4(glm::dvec3(model.bounds().centre()), 1.0));
    const double px_per_unit =
        scale * pixels_per_unit(camera, ortho, centre, model.bounds().radius() * scale, params.height);
    LodUse use;
    use.levels = model.lod_count();
    if (params.lod_auto) use.level = choose_lod(model.lod_errors(), px_per_unit, params.lod_error_px);
    use.triangles = model.triangles(use.level);
    use.error_px = model.lod_errors()[use.level] * px_per_unit;
    uses.push_back(use);
  }
  return uses;
}

void cull(HiddenFaces faces) {
  if (faces == HiddenFaces::None) {
    glDisable(GL_CULL_FACE);
    return;
  }
  glEnable(GL_CULL_FACE);
  glCullFace(faces == HiddenFaces::Back ? GL_BACK : GL_FRONT);
}

HiddenFaces other_side(HiddenFaces faces) {
  if (faces == HiddenFaces::None) return HiddenFaces::None;
  return faces == HiddenFaces::Back ? HiddenFaces::Front : HiddenFaces::Back;
}

// Which faces of an object a pass skips.
struct FaceSkip {
  HiddenFaces hidden = HiddenFaces::None;
  // The object has holes whose caps may face the camera: the skipped side
  // is drawn after all wherever one of them shows (redraw_where_caps_show).
  bool unless_caps_show = false;
};

// After an object was drawn with `hidden` skipped: draws its caps with the
// pass's program and tests but writing nothing, counting the samples that
// pass, and draws the skipped side (`draw`) only if any did. A skipped face
// that would have shown is met by its ray after the ray came in through a
// hole (a closed surface is entered through a face turned toward the
// viewer), so past a cap turned toward the camera and nearer than that
// face, which passes every test the face would. `query` keeps the answer.
template <typename Draw>
void redraw_where_caps_show(const GpuModel& model, std::size_t lod, HiddenFaces hidden, gpu::Query& query,
                            Draw&& draw) {
  GLboolean depth_writes = GL_TRUE;
  GLint stencil_writes = 0;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_writes);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &stencil_writes);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glStencilMask(0);
  query = gpu::Query::create(GL_ANY_SAMPLES_PASSED);
  glBeginQuery(GL_ANY_SAMPLES_PASSED, query.id());
  model.draw_caps(lod);  // their hidden side skipped like the mesh's: they are wound like it
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(depth_writes);
  glStencilMask(static_cast<GLuint>(stencil_writes));
  glBeginConditionalRender(query.id(), GL_QUERY_WAIT);
  cull(other_side(hidden));
  draw();
  glEndConditionalRender();
  cull(hidden);
}

}  // namespace

gpu::NormalDepthTarget& Renderer::normal_depth_for(int width, int height, int samples) {
  if (!normal_depth_ || !normal_depth_->matches(width, height, samples)) {
    normal_depth_.reset();
    normal_depth_.emplace(width, height, samples);
  }
  return *normal_depth_;
}

gpu::ShadowMap& Renderer::shadow_map_for(int size) {
  if (!shadow_map_ || shadow_map_->size() != size) {
    shadow_map_.reset();
    shadow_map_.emplace(size);
  }
  return *shadow_map_;
}

const GpuModel& Renderer::floor_for(const scene::Bounds& b, const FloorParams& params, bool textured) {
  const std::shared_ptr<const scene::Texture> image = textured ? params.image : nullptr;
  if (!floor_ || floor_size_ != params.size || floor_repeat_ != params.texture_repeat || floor_image_ != image ||
      floor_bounds_.min != b.min || floor_bounds_.max != b.max) {
    floor_.reset();
    floor_.emplace(make_floor(b, params.size, params.texture_repeat, image));
    floor_bounds_ = b;
    floor_size_ = params.size;
    floor_repeat_ = params.texture_repeat;
    floor_image_ = image;
  }
  return *floor_;
}

gpu::RenderTarget& Renderer::target_for(int width, int height, int samples) {
  if (!target_ || !target_->matches(width, height, samples)) {
    target_.reset();  // free the old storage before allocating the new
    // On a CPU rasterizer the pack happens inside glReadPixels whatever the
    // destination, and straight into memory measured faster there.
    target_.emplace(width, height, samples,
                    *real_gpu_ ? gpu::ReadbackPath::PixelBuffer : gpu::ReadbackPath::ClientMemory);
  }
  return *target_;
}

RenderOutput Renderer::render(const std::vector<RenderObject>& objects, const RenderParams& params) {
  if (objects.empty()) throw gpu::GpuError("a render needs at least one object");
  ModelTraits traits;
  std::vector<ScenePart> parts;
  for (const RenderObject& o : objects) {
    traits.has_textures |= o.model.has_textures();
    traits.has_normal_maps |= o.model.has_normal_maps();
    traits.has_vertex_colors |= o.model.has_vertex_colors();
    traits.hard_edged |= o.model.creases().hard_edged(params.outline.crease_angle_deg);
    parts.push_back({o.model.bounds(), o.model.origin(), o.transform, o.model.extremes()});
  }
  const PassPlan plan = plan_passes(params, traits);
  // Everything below works in the frame's coordinates: scene coordinates
  // less a point at the scene's middle. Each object's matrix takes its
  // (origin-relative) mesh there; it was composed in double and is only
  // rounded to float now.
  const SceneFrame frame = frame_scene(parts);
  const scene::Bounds& bounds = frame.bounds;
  std::vector<glm::mat4> model_matrix;
  std::vector<glm::mat3> normal_matrix;
  for (const glm::dmat4& m : frame.matrices) {
    model_matrix.emplace_back(m);
    // Inverse-transpose of the upper 3×3: normals stay perpendicular to the
    // surface under non-uniform scale.
    normal_matrix.emplace_back(glm::transpose(glm::inverse(glm::dmat3(m))));
  }
  auto set_object = [&](gpu::Program& program, std::size_t i) {
    program.set("u_model", model_matrix[i]);
    program.set("u_normal_matrix", normal_matrix[i]);
  };
  RenderOutput out;
  out.plan = plan.describe();
  out.lods = choose_levels(objects, frame, params);
  // Every pass draws an object at the same level, so the hull, the shadow
  // and the edges all follow the surface that was shaded.
  auto lod_of = [&](std::size_t i) { return out.lods[i].level; };
  // The faces of object i that cannot show through `view_projection`. An
  // object with holes whose caps do not all turn away from `viewer` skips
  // them too in a pass that can check its caps (`caps_checked`), else none.
  auto culling_for = [&](std::size_t i, const glm::dmat4& view_projection, const Viewer& viewer,
                         bool caps_checked) {
    FaceSkip skip;
    if (!face_culling_) return skip;
    const GpuModel& model = objects[i].model;
    const scene::Enclosure enclosure = model.enclosure(lod_of(i));
    const bool caps_away = caps_face_away(model.caps(lod_of(i)), enclosure, frame.matrices[i], viewer);
    if (!caps_away && !caps_checked) return skip;
    skip.hidden = hidden_faces(enclosure, frame.matrices[i], view_projection, model.bounds());
    skip.unless_caps_show = !caps_away && skip.hidden != HiddenFaces::None;
    return skip;
  };
  if (!real_gpu_) {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    real_gpu_ = !gpu::software_rasterizer(name ? name : "");
  }
  // GPU time only on a GPU: a CPU rasterizer's queries do not see its
  // raster threads (they stamp commands as they are recorded), and llvmpipe
  // records a query into every screen tile, which costs a pass over the
  // image per query (toond_bench sweep shows it).
  PassTimer timer(out.timings, *real_gpu_);
  // Each pass goes to the driver as soon as it is recorded: llvmpipe then
  // rasterizes it on its threads while this one records the next.
  auto end_pass = [&](Pass pass) {
    glFlush();
    timer.mark(pass);
  };

  std::optional<ShadowFit> shadow;
  if (plan.has(Pass::Shadow)) {
    const Light& caster = params.lights[static_cast<std::size_t>(plan.shadow_light)];
    shadow = fit_shadow(caster.direction, bounds, params.shadows.map_size);
    gpu::ShadowMap& map = shadow_map_for(params.shadows.map_size);
    map.bind_for_drawing();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    // Slope-scaled bias for surfaces the light grazes; the normal offset in
    // the main pass handles the rest.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 2.0f);
    gpu::Program& program = programs_.get("shadow.vert", "shadow.frag", {});
    program.use();
    program.set("u_light_view_projection", glm::mat4(shadow->view_projection));
    for (std::size_t i = 0; i < objects.size(); ++i) {
      // The nearest surface seen from the light is the same with the far
      // side skipped, so the map is too.
      cull(culling_for(i, shadow->view_projection, Viewer{glm::dvec3(0.0), glm::normalize(caster.direction), true},
                       false)
               .hidden);
      program.set("u_model", model_matrix[i]);
      objects[i].model.bind();
      objects[i].model.draw_all(lod_of(i));
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    check_gl("shadow pass");
    end_pass(Pass::Shadow);
  }

  // Supersampling draws everything `ss` times larger, pixel sizes included,
  // then averages back down; the look is the same, the edges smoother.
  const int ss = plan.supersample;
  const float px = static_cast<float>(ss);
  const int draw_width = params.width * ss;
  const int draw_height = params.height * ss;
  gpu::RenderTarget& target = target_for(draw_width, draw_height, plan.samples);
  out.samples = target.samples();
  target.bind_for_drawing();
  const CameraSetup camera = fit_camera(params.camera, bounds,
                                        static_cast<double>(params.width) / params.height, frame.outline);
  const glm::mat4 view_projection = camera.view_projection();
  const bool ortho = params.camera.projection == Projection::Orthographic;
  // Every outline method draws this one width, in drawn pixels.
  const float outline_px = static_cast<float>(outline_width_px(params.outline, camera, ortho, params.height)) * px;
  std::vector<FaceSkip> skip(objects.size());  // of the main pass and the edge prepass
  // The main pass's cap checks, read once the image is back (when their
  // answers are ready anyway) to report which objects drew both sides.
  std::vector<gpu::Query> main_cap_checks(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    skip[i] = culling_for(i, camera.projection * camera.view,
                          Viewer{camera.eye, glm::normalize(camera.target - camera.eye),
                                 params.camera.projection == Projection::Orthographic},
                          true);
    out.lods[i].culled = skip[i].hidden;
  }

  glEnable(GL_FRAMEBUFFER_SRGB);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xff);
  glClearColor(params.background.r, params.background.g, params.background.b, params.background.a);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  // Main pass: shade, and mark every covered sample in the stencil so the
  // hull outline can only land outside the model.
  {
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    // Light positions are in scene coordinates (a lone model's own); the
    // render works relative to the frame's origin, so point lights move
    // with it.
    std::vector<glm::vec3> light_vec;
    std::vector<glm::vec3> light_color;
    std::vector<int> light_is_point;
    std::vector<float> light_radius;
    for (const Light& l : params.lights) {
      if (l.kind == LightKind::Point) {
        light_vec.push_back(glm::vec3(l.position - frame.origin));
      } else {
        const double len = glm::length(l.direction);
        // A zero direction has no way to travel; it lights nothing.
        if (!(len > 0.0)) continue;
        light_vec.push_back(glm::vec3(-l.direction / len));
      }
      light_color.push_back(l.color);
      light_is_point.push_back(l.kind == LightKind::Point ? 1 : 0);
      light_radius.push_back(static_cast<float>(l.radius));
    }
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    std::vector<float> ramp_at;
    std::vector<glm::vec3> ramp_color;
    for (const RampStop& stop : params.ramp) {
      ramp_at.push_back(stop.at);
      ramp_color.push_back(stop.color);
    }
    // Uniforms every main-pass program of this render shares.
    auto set_main_uniforms = [&](gpu::Program& program) {
      program.set("u_view_projection", view_projection);
      program.set("u_ambient", params.ambient);
      program.set("u_steps", static_cast<float>(params.steps));
      program.set("u_eye", glm::vec3(camera.eye));
      program.set("u_view_dir", glm::vec3(forward));
      program.set("u_orthographic", params.camera.projection == Projection::Orthographic ? 1 : 0);
      program.set_array("u_light_vec", light_vec);
      program.set_array("u_light_color", light_color);
      program.set_array("u_light_is_point", light_is_point);
      program.set_array("u_light_radius", light_radius);
      program.set("u_specular_color", params.specular.color);
      program.set("u_shininess", params.specular.shininess);
      program.set("u_specular_threshold", params.specular.threshold);
      program.set("u_specular_strength", params.specular.strength);
      program.set("u_rim_color", params.rim.color);
      program.set("u_rim_power", params.rim.power);
      program.set("u_rim_strength", params.rim.strength);
      program.set("u_rim_threshold", params.rim.threshold);
      program.set("u_contour_color", params.contour.color);
      program.set("u_contour_width", params.contour.width_px * px);
      program.set("u_contour_threshold", params.contour.threshold);
      program.set("u_halftone_cell", params.halftone.cell_px * px);
      program.set("u_halftone_angle", static_cast<float>(glm::radians(params.halftone.angle_deg)));
      program.set("u_halftone_ink", params.halftone.ink);
      program.set("u_halftone_ink_mix", params.halftone.ink_mix);
      program.set("u_two_tone_threshold", params.two_tone.threshold);
      program.set("u_two_tone_shadow", params.two_tone.shadow_factor);
      program.set_array("u_ramp_at", ramp_at);
      program.set_array("u_ramp_color", ramp_color);
    };
    auto set_shadow_uniforms = [&](gpu::Program& program) {
      program.set("u_shadow_matrix", glm::mat4(shadow->view_projection));
      program.set("u_shadow_light", plan.shadow_light);
      program.set("u_shadow_texel", 1.0f / static_cast<float>(params.shadows.map_size));
      program.set("u_shadow_offset", static_cast<float>(shadow->texel_world * params.shadows.bias_texels));
      glBindTextureUnit(1, shadow_map_->texture());
      program.set("u_shadow_map", 1);
    };
    auto draw_object = [&](std::size_t i) {
      const GpuModel& model = objects[i].model;
      for (const scene::Submesh& sub : model.submeshes(lod_of(i))) {
        const GpuMaterial& material = model.materials()[static_cast<std::size_t>(sub.material)];
        std::vector<std::string> defines = plan.main_defines;
        if (material.unlit) {
          // An unlit material shows its base colour as it is: the flat mode.
          std::replace_if(defines.begin(), defines.end(),
                          [](const std::string& d) { return d == "MODE_CEL" || d == "MODE_PHONG"; }, "MODE_FLAT");
        }
        const bool masked = material.alpha_cutoff >= 0.0f;
        // A masked material's texture gives its shape: it is sampled even
        // where the request leaves textures out (base white).
        const bool textured = (plan.sample_textures || masked) && material.texture >= 0;
        if (textured) defines.push_back("HAS_TEXTURE");
        if (masked) defines.push_back("ALPHA_MASK");
        const bool normal_mapped = plan.use_normal_maps && material.normal_texture >= 0;
        if (normal_mapped) defines.push_back("NORMAL_MAP");
        // A shade colour changes nothing where nothing is lit to blend from.
        const auto shade = params.shade_colors.find(material.name);
        const bool shaded = shade != params.shade_colors.end() && params.mode != ShadingMode::Flat;
        if (shaded) defines.push_back("SHADE_COLOR");
        gpu::Program& program = programs_.get("toon.vert", "toon.frag", defines);
        program.use();
        set_main_uniforms(program);
        set_object(program, i);
        program.set("u_base_color", material.diffuse);
        if (masked) {
          program.set("u_opacity", material.opacity);
          program.set("u_alpha_cutoff", material.alpha_cutoff);
        }
        if (shaded) program.set("u_shade_color", shade->second);
        if (normal_mapped) {
          glBindTextureUnit(2, model.texture(material.normal_texture));
          program.set("u_normal_map", 2);
        }
        if (textured) {
          glBindTextureUnit(0, model.texture(material.texture));
          program.set("u_diffuse_map", 0);
        }
        if (shadow) set_shadow_uniforms(program);
        model.draw(sub);
      }
    };
    for (std::size_t i = 0; i < objects.size(); ++i) {
      objects[i].model.bind();
      cull(skip[i].hidden);
      draw_object(i);
      if (skip[i].unless_caps_show) {
        redraw_where_caps_show(objects[i].model, lod_of(i), skip[i].hidden, main_cap_checks[i],
                               [&] { draw_object(i); });
      }
    }
    glDisable(GL_CULL_FACE);
    check_gl("main pass");
    end_pass(Pass::Main);

    if (plan.has(Pass::Floor)) {
      // Same shading as the model, but no stencil mark: the floor is never
      // outlined, and the model's outline may cross it.
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      const bool textured = plan.floor_textured && params.floor.image;
      const GpuModel& floor = floor_for(bounds, params.floor, textured);
      std::vector<std::string> defines = plan.main_defines;
      if (textured) defines.push_back("HAS_TEXTURE");
      gpu::Program& program = programs_.get("toon.vert", "toon.frag", defines);
      program.use();
      set_main_uniforms(program);
      // The floor is made in frame coordinates already.
      program.set("u_model", glm::mat4(1.0f));
      program.set("u_normal_matrix", glm::mat3(1.0f));
      program.set("u_base_color", params.floor.color);
      if (textured) {
        glBindTextureUnit(0, floor.texture(0));
        program.set("u_diffuse_map", 0);
      }
      if (shadow) set_shadow_uniforms(program);
      floor.bind();
      floor.draw_all();
      check_gl("floor pass");
      end_pass(Pass::Floor);
    }
  }

  // Hull and wireframe lines take their colour the same way.
  // Object by object, each under its own matrices.
  // `faces` says which side of object i's faces the pass may skip.
  auto set_outline_colour_and_draw = [&](gpu::Program& program, auto faces) {
    program.set("u_outline_color", params.outline.color);
    program.set("u_darken", params.outline.darken);
    auto draw_object = [&](std::size_t i) {
      const GpuModel& model = objects[i].model;
      if (plan.outline_defines.empty()) {
        model.draw_all(lod_of(i));
        return;
      }
      // The colour comes from each material, so draw material by material.
      for (const scene::Submesh& sub : model.submeshes(lod_of(i))) {
        const GpuMaterial& material = model.materials()[static_cast<std::size_t>(sub.material)];
        program.set("u_base_color", material.diffuse);
        const bool textured = material.texture >= 0;
        program.set("u_has_texture", textured ? 1 : 0);
        if (textured) {
          glBindTextureUnit(0, model.texture(material.texture));
          program.set("u_diffuse_map", 0);
        }
        model.draw(sub);
      }
    };
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const FaceSkip object_skip = faces(i);
      cull(object_skip.hidden);
      set_object(program, i);
      objects[i].model.bind();
      draw_object(i);
      if (object_skip.unless_caps_show) {
        gpu::Query check;
        redraw_where_caps_show(objects[i].model, lod_of(i), object_skip.hidden, check, [&] { draw_object(i); });
      }
    }
    glDisable(GL_CULL_FACE);
  };

  if (plan.has(Pass::HullOutline)) {
    glStencilFunc(GL_NOTEQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    gpu::Program& program = programs_.get("hull.vert", "hull.frag", plan.outline_defines);
    program.use();
    program.set("u_view_projection", view_projection);
    // projection[1][1] maps a view-space height at depth w to NDC, and NDC
    // spans `height` pixels over 2 units.
    const double world_per_px = 2.0 / (camera.projection[1][1] * draw_height);
    program.set("u_world_per_px_at_w1", static_cast<float>(world_per_px));
    program.set("u_width", outline_px);
    program.set("u_viewport_px", glm::vec2(static_cast<float>(draw_width), static_cast<float>(draw_height)));
    program.set("u_eye", glm::vec3(camera.eye));
    program.set("u_view_dir", glm::vec3(glm::normalize(camera.target - camera.eye)));
    program.set("u_orthographic", ortho ? 1 : 0);
    // The stencil keeps the hull off the model, so its faces toward the
    // camera may draw the ring: where a closed model's back faces may be
    // skipped, the hull's may too. Its front faces lie nearer than its back
    // ones, so they pass every depth test (a floor's) the back ones would.
    // The hull stands out of the model's box by up to 3 widths (mitred
    // corners), and must not be cut by the near or far plane either: where
    // it is, its back faces show through the cut.
    // A pixel's size grows with the depth w, which the offset itself adds to.
    const double k = 3.0 * outline_px * world_per_px;
    double w_max = 1.0;
    if (!ortho) {
      for (int corner = 0; corner < 8; ++corner) {
        w_max = std::max(w_max, (camera.projection * camera.view * glm::dvec4(bounds.corner(corner), 1.0)).w);
      }
    }
    const double reach = ortho ? k : (k < 0.5 ? k * w_max / (1.0 - k) : std::numeric_limits<double>::infinity());
    const glm::dmat4 clip = camera.projection * camera.view;
    set_outline_colour_and_draw(program, [&](std::size_t i) {
      const GpuModel& model = objects[i].model;
      FaceSkip hull;
      if (skip[i].hidden == HiddenFaces::None) return hull;
      hull.hidden = hidden_faces(model.enclosure(lod_of(i)), frame.matrices[i], clip, model.bounds(), reach);
      // The hull's holes move with its offset and may turn toward the
      // camera where the model's do not: its own caps, offset like it
      // (they share its vertices), are checked.
      hull.unless_caps_show = hull.hidden != HiddenFaces::None && !model.caps(lod_of(i)).empty();
      return hull;
    });
    check_gl("hull outline pass");
    end_pass(Pass::HullOutline);
  }

  if (plan.has(Pass::Wireframe)) {
    // After the model: its front faces hide the back-face lines except where
    // they show past the silhouette or over folds. Line pixels of back faces
    // lie behind the front faces they border, so no stencil is needed.
    glDisable(GL_STENCIL_TEST);
    std::vector<std::string> defines = plan.outline_defines;
    defines.push_back("LINE_SEGMENT");
    gpu::Program& program = programs_.get(std::vector<std::string>{"wire.vert", "wire.geom", "hull.frag"}, defines);
    program.use();
    program.set("u_view_projection", view_projection);
    program.set("u_viewport", glm::vec2(static_cast<float>(draw_width), static_cast<float>(draw_height)));
    // Half of each line lies inside the silhouette, under the front faces:
    // lines twice as wide leave `width` pixels showing.
    program.set("u_line_px", 2.0f * outline_px);
    program.set("u_half_line_px", outline_px);
    program.set("u_eye", glm::vec3(camera.eye));
    program.set("u_view_dir", glm::vec3(glm::normalize(camera.target - camera.eye)));
    program.set("u_orthographic", ortho ? 1 : 0);
    // The line's coverage picks the samples it writes, each written opaque.
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    set_outline_colour_and_draw(program, [](std::size_t) { return FaceSkip{}; });
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    check_gl("wireframe pass");
    end_pass(Pass::Wireframe);
  }

  if (plan.has(Pass::Edges)) {
    // Silhouettes are placed by the share of a pixel the model covers, which
    // takes samples; creases and depth jumps are found on whole pixels, so
    // a pass drawing creases alone does with one.
    const int prepass_samples = plan.creases_only ? 1 : kSilhouetteSamples;
    gpu::NormalDepthTarget& normals = normal_depth_for(draw_width, draw_height, prepass_samples);
    normals.bind_for_drawing();
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    gpu::Program& prepass = programs_.get("toon.vert", "normal_depth.frag", {});
    prepass.use();
    prepass.set("u_view_projection", view_projection);
    prepass.set("u_eye", glm::vec3(camera.eye));
    prepass.set("u_view_dir", glm::vec3(glm::normalize(camera.target - camera.eye)));
    prepass.set("u_orthographic", params.camera.projection == Projection::Orthographic ? 1 : 0);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      cull(skip[i].hidden);
      set_object(prepass, i);
      objects[i].model.bind();
      objects[i].model.draw_all(lod_of(i));
      if (skip[i].unless_caps_show) {
        gpu::Query check;
        redraw_where_caps_show(objects[i].model, lod_of(i), skip[i].hidden, check,
                               [&] { objects[i].model.draw_all(lod_of(i)); });
      }
    }
    glDisable(GL_CULL_FACE);
    if (normals.needs_resolve()) {
      normals.bind_for_resolve();
      glDisable(GL_DEPTH_TEST);
      gpu::Program& resolve = programs_.get("fullscreen.vert", "normal_depth_resolve.frag", {});
      resolve.use();
      glBindTextureUnit(0, normals.sample_texture());
      resolve.set("u_samples", 0);
      resolve.set("u_sample_count", normals.samples());
      glBindVertexArray(fullscreen_vao_.id());
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    check_gl("edge prepass");
    end_pass(Pass::EdgePrepass);

    target.bind_for_drawing();
    glDisable(GL_DEPTH_TEST);
    gpu::Program& edges = programs_.get("fullscreen.vert", "edges.frag",
                                        plan.creases_only ? std::vector<std::string>{"CREASES_ONLY"}
                                                          : std::vector<std::string>{});
    edges.use();
    glBindTextureUnit(0, normals.texture());
    glBindTextureUnit(1, normals.coverage_texture());
    edges.set("u_normal_depth", 0);
    edges.set("u_coverage", 1);
    edges.set("u_half_width", 0.5f * outline_px);
    edges.set("u_depth_threshold", params.outline.depth_threshold * 2.0f * bounds.radius());
    edges.set("u_cos_crease", static_cast<float>(std::cos(glm::radians(params.outline.crease_angle_deg))));
    edges.set("u_edge_color", params.outline.color);
    // The shader gives each pixel the share of it the line covers.
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(fullscreen_vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    check_gl("edge pass");
    end_pass(Pass::Edges);
  }

  glBindVertexArray(0);
  glDisable(GL_STENCIL_TEST);
  // The multisample resolve is a blit inside read_back(); its time is part
  // of the readback figure, since the readback waits for it anyway.
  out.image = target.read_back();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!main_cap_checks[i]) continue;
    GLuint shown = 0;
    glGetQueryObjectuiv(main_cap_checks[i].id(), GL_QUERY_RESULT, &shown);
    if (shown) out.lods[i].culled = HiddenFaces::None;
  }
  check_gl("readback");
  timer.mark(Pass::Readback);
  if (plan.has(Pass::Downsample)) {
    out.image = image::downsample_box(out.image, ss);
    timer.mark(Pass::Downsample);
  }
  return out;
}

}  // namespace toond::render
