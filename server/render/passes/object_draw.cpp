#include "render/passes/object_draw.h"

#include "render/frame/texture_unit.h"
#include "render/passes/pass_context.h"

namespace toond::render {
namespace {

HiddenFaces other_side(HiddenFaces faces) {
  if (faces == HiddenFaces::None) return HiddenFaces::None;
  return faces == HiddenFaces::Back ? HiddenFaces::Front : HiddenFaces::Back;
}

// After an object was drawn with `hidden` skipped: draws its caps with the
// pass's program and tests but writing nothing, counting the samples that
// pass, and draws the skipped side (`draw`) only if any did. A skipped face
// that would have shown is met by its ray after the ray came in through a
// hole (a closed surface is entered through a face turned toward the
// viewer), so past a cap turned toward the camera and nearer than that
// face, which passes every test the face would. `query` keeps the answer.
void redraw_where_caps_show(const GpuModel& model, std::size_t lod, DrawPacing* pacing, HiddenFaces hidden,
                            gpu::Query& query, const std::function<void()>& draw) {
  GLboolean depth_writes = GL_TRUE;
  GLint stencil_writes = 0;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_writes);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &stencil_writes);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glStencilMask(0);
  query = gpu::Query::create(GL_ANY_SAMPLES_PASSED);
  glBeginQuery(GL_ANY_SAMPLES_PASSED, query.id());
  model.draw_caps(lod, pacing);  // their hidden side skipped like the mesh's: they are wound like it
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

void cull(HiddenFaces faces) {
  if (faces == HiddenFaces::None) {
    glDisable(GL_CULL_FACE);
    return;
  }
  glEnable(GL_CULL_FACE);
  glCullFace(faces == HiddenFaces::Back ? GL_BACK : GL_FRONT);
}

void draw_objects(const PassContext& context, const ObjectDraw& how) {
  const FrameContext& frame = context.frame;
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    const GpuModel& model = context.model(i);
    const FaceSkip skip = how.faces(i);
    cull(skip.hidden);
    context.blocks.bind_object(i);
    model.bind();
    how.draw(i);
    if (skip.unless_caps_show) {
      gpu::Query local;
      gpu::Query& check = how.cap_checks ? (*how.cap_checks)[i] : local;
      redraw_where_caps_show(model, frame.lod_of(i), context.pacing, skip.hidden, check,
                             [&] { (how.redraw ? how.redraw : how.draw)(i); });
    }
  }
  glDisable(GL_CULL_FACE);
}

void draw_whole_object(const PassContext& context, std::size_t i) {
  context.model(i).draw_all(context.frame.lod_of(i), context.pacing);
}

namespace {

GLint gl_wrap(scene::TextureWrap wrap) {
  switch (wrap) {
    case scene::TextureWrap::ClampToEdge:
      return GL_CLAMP_TO_EDGE;
    case scene::TextureWrap::MirroredRepeat:
      return GL_MIRRORED_REPEAT;
    case scene::TextureWrap::Repeat:
      break;
  }
  return GL_REPEAT;
}

// A texture's sampling lives on the texture object, which materials may
// share with other samplings: set before each material's draws.
void sample_as(GLuint texture, const DrawnMaterial& drawn) {
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, drawn.nearest_magnification ? GL_NEAREST : GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER,
                      drawn.nearest_minification ? GL_NEAREST_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, gl_wrap(drawn.wrap_s));
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, gl_wrap(drawn.wrap_t));
}

}  // namespace

void bind_material(const PassContext& context, std::size_t i, int material) {
  context.blocks.bind_material(i, material);
  const DrawnMaterial& drawn = context.frame.material(i, material);
  const GpuModel& model = context.model(i);
  GLuint texture = 0;
  if (drawn.image) {
    texture = model.image_texture(drawn.image);
  } else if (drawn.texture >= 0) {
    texture = model.texture(drawn.texture);
  }
  if (texture == 0) return;
  sample_as(texture, drawn);
  glBindTextureUnit(texture_unit::kDiffuse, texture);
}

void bind_own_material(const GpuModel& model, int material) {
  model.bind_material(material);
  const int texture = model.materials()[static_cast<std::size_t>(material)].texture;
  if (texture >= 0) glBindTextureUnit(texture_unit::kDiffuse, model.texture(texture));
}

void draw_by_material(const PassContext& context, std::size_t i) {
  const GpuModel& model = context.model(i);
  for (const scene::Submesh& sub : model.submeshes(context.frame.lod_of(i))) {
    bind_material(context, i, sub.material);
    model.draw(sub, context.pacing);
  }
}

}  // namespace toond::render
