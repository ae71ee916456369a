#include "pipeline/render_params_wire.h"

#include <algorithm>
#include <string>

namespace toond::pipeline {

// Every type built here is the renderer's; spelling render:: on each would
// hide the mapping.
using namespace render;

namespace {

using nlohmann::json;

glm::vec3 vec3_of(const json& a) { return {a.at(0).get<float>(), a.at(1).get<float>(), a.at(2).get<float>()}; }

glm::dvec3 dvec3_of(const json& a) { return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()}; }

// `sheet.pixel_art`; the schema has checked each palette entry is #rrggbb.
SheetParams::PixelArt pixel_art_of(const json& a) {
  SheetParams::PixelArt art;
  art.scale = a.at("scale").get<int>();
  art.colors = a.at("colors").get<int>();
  if (a.contains("palette")) {
    for (const json& entry : a.at("palette")) {
      const std::string hex = entry.get<std::string>();
      const unsigned long rgb = std::stoul(hex.substr(1), nullptr, 16);
      art.palette.push_back(
          {static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8), static_cast<std::uint8_t>(rgb)});
    }
  }
  art.dither = a.at("dither").get<bool>();
  art.lines = a.at("lines").get<std::string>() == "as_given" ? SheetParams::PixelArt::Lines::AsGiven
                                                             : SheetParams::PixelArt::Lines::Sprite;
  return art;
}

// A `clip` field: a name, or (a number) an index.
void read_clip(const json& clip, std::string& name, int& index) {
  if (clip.is_string()) {
    name = clip.get<std::string>();
  } else {
    index = clip.get<int>();
  }
}

// A `range` field, [start, end] in seconds; the pipeline holds it to the
// clip (pipeline/clips.h).
std::optional<scene::ClipRange> range_of(const json& a) {
  if (!a.contains("range")) return std::nullopt;
  const json& range = a.at("range");
  return scene::ClipRange{range.at(0).get<double>(), range.at(1).get<double>()};
}

AnimationParams animation_of(const json& a) {
  AnimationParams animation;
  read_clip(a.at("clip"), animation.clip, animation.clip_index);
  animation.time = a.at("time").get<double>();
  animation.range = range_of(a);
  return animation;
}

SheetClip sheet_clip_of(const json& a) {
  SheetClip clip;
  read_clip(a.at("clip"), clip.clip, clip.clip_index);
  if (a.contains("frames")) clip.frames = a.at("frames").get<int>();
  if (a.contains("fps")) clip.fps = a.at("fps").get<double>();
  clip.range = range_of(a);
  clip.loop = a.at("loop").get<bool>();
  return clip;
}

// The `sheet` block with its absent fields taken from the camera: a sheet
// turns the view the request already has.
SheetParams sheet_of(const json& s, const CameraParams& camera) {
  SheetParams sheet;
  sheet.frames = s.at("frames").get<int>();
  sheet.columns = s.contains("columns") ? s.at("columns").get<int>() : sheet.frames;
  sheet.yaw_start_deg = s.contains("yaw_start") ? s.at("yaw_start").get<double>() : camera.yaw_deg;
  sheet.yaw_step_deg = s.contains("yaw_step") ? s.at("yaw_step").get<double>() : 360.0 / sheet.frames;
  if (s.contains("pitches")) {
    for (const json& pitch : s.at("pitches")) sheet.pitches_deg.push_back(pitch.get<double>());
  } else {
    sheet.pitches_deg.push_back(camera.pitch_deg);
  }
  sheet.padding = s.at("padding").get<int>();
  if (s.contains("pixel_art")) sheet.pixel_art = pixel_art_of(s.at("pixel_art"));
  sheet.animate = s.at("animate").get<bool>();
  sheet.frame_ms = s.at("frame_ms").get<int>();
  sheet.pack = s.at("pack").get<bool>();
  sheet.power_of_two = s.at("power_of_two").get<bool>();
  if (s.contains("layers")) {
    // The schema lets color and lines alone in.
    for (const json& layer : s.at("layers")) sheet.layers.push_back(layer == "lines" ? Output::Lines : Output::Color);
  }
  if (s.contains("animation")) {
    const json& a = s.at("animation");
    sheet.clip_list = a.is_array();
    for (const json& entry : a.is_array() ? a : json::array({a})) sheet.clips.push_back(sheet_clip_of(entry));
  }
  return sheet;
}

Output output_of(const std::string& name) {
  if (name == "lines") return Output::Lines;
  if (name == "depth") return Output::Depth;
  if (name == "normal") return Output::Normal;
  if (name == "id") return Output::Id;
  if (name == "svg") return Output::Svg;
  return Output::Color;
}

// What is drawn, and the image it is drawn into.
void read_scene(const json& j, RenderParams& p) {
  p.model = j.value("model", "");
  if (const auto objects = j.find("objects"); objects != j.end()) {
    for (const json& o : *objects) {
      SceneObject object;
      object.model = o.at("model").get<std::string>();
      const json& t = o.at("transform");
      object.translate = dvec3_of(t.at("translate"));
      object.rotate_deg = dvec3_of(t.at("rotate"));
      const json& s = t.at("scale");
      object.scale = s.is_array() ? dvec3_of(s) : glm::dvec3(s.get<double>());
      p.objects.push_back(object);
    }
  }
  p.width = j.at("width").get<int>();
  p.height = j.at("height").get<int>();
  const json& bg = j.at("background");
  p.background = glm::vec4(srgb_to_linear(vec3_of(bg)), bg.size() > 3 ? bg[3].get<float>() : 1.0f);
}

void read_camera(const json& j, RenderParams& p) {
  const json& cam = j.at("camera");
  p.camera.projection = cam.at("projection") == "orthographic" ? Projection::Orthographic : Projection::Perspective;
  p.camera.yaw_deg = cam.at("yaw").get<double>();
  p.camera.pitch_deg = cam.at("pitch").get<double>();
  p.camera.fov_deg = cam.at("fov").get<double>();
  p.camera.distance = cam.at("distance").get<double>();
  p.camera.zoom = cam.at("zoom").get<double>();
  p.camera.shift = glm::dvec2(cam.at("shift")[0].get<double>(), cam.at("shift")[1].get<double>());
}

// The lights and how they add up.
void read_lights(const json& j, RenderParams& p) {
  for (const json& l : j.at("lights")) {
    Light light;
    light.kind = l.at("type") == "point" ? LightKind::Point : LightKind::Directional;
    light.direction = dvec3_of(l.at("direction"));
    if (l.contains("position")) light.position = dvec3_of(l.at("position"));
    light.radius = l.at("radius").get<double>();
    light.color = srgb_to_linear(vec3_of(l.at("color"))) * l.at("intensity").get<float>();
    light.space = l.at("space") == "view" ? LightSpace::View : LightSpace::Model;
    p.lights.push_back(light);
  }
  p.light_combine = j.at("light_combine") == "sum" ? LightCombine::Sum : LightCombine::Max;
  p.ambient = j.at("ambient").get<float>();
}

// The bands, ramps and base colour of the main pass.
void read_shading(const json& j, RenderParams& p) {
  const json& shading = j.at("shading");
  const std::string mode = shading.at("mode");
  p.mode = mode == "phong" ? ShadingMode::Phong : mode == "flat" ? ShadingMode::Flat : ShadingMode::Cel;
  p.base = shading.at("base") == "white" ? BaseColor::White : BaseColor::Material;
  p.steps = shading.at("steps").get<int>();
  const std::string rounding = shading.at("rounding");
  p.band_aa = shading.at("band_aa").get<bool>();
  const json& two_tone = shading.at("two_tone");
  p.two_tone.enabled = two_tone.at("enabled").get<bool>();
  p.two_tone.threshold = two_tone.at("threshold").get<float>();
  p.two_tone.shadow_factor = two_tone.at("shadow_factor").get<float>();
  for (const json& stop : shading.at("ramp")) {
    RampStop r;
    r.at = stop.at("at").get<float>();
    // A grey value is a level of light, linear already; a colour is sRGB
    // like every colour on the wire.
    r.color =
        stop.contains("color") ? srgb_to_linear(vec3_of(stop.at("color"))) : glm::vec3(stop.at("value").get<float>());
    p.ramp.push_back(r);
  }
  p.ramp_image = shading.at("ramp_image").get<std::string>();
  for (const auto& [name, colour] : shading.at("shade_colors").items()) {
    p.shade_colors[name] = srgb_to_linear(vec3_of(colour));
  }
  std::stable_sort(p.ramp.begin(), p.ramp.end(), [](const RampStop& a, const RampStop& b) { return a.at < b.at; });
  p.rounding = rounding == "floor" ? Rounding::Floor : rounding == "round" ? Rounding::Round : Rounding::Ceil;
}

// The effects the main pass adds: specular, rim, halftone, contour.
void read_effects(const json& j, RenderParams& p) {
  const json& specular = j.at("specular");
  p.specular.enabled = specular.at("enabled").get<bool>();
  p.specular.color = srgb_to_linear(vec3_of(specular.at("color")));
  p.specular.shininess = specular.at("shininess").get<float>();
  p.specular.threshold = specular.at("threshold").get<float>();
  p.specular.strength = specular.at("strength").get<float>();
  p.specular.source = specular.at("source") == "all" ? SpecularSource::All : SpecularSource::Material;

  const json& rim = j.at("rim");
  p.rim.enabled = rim.at("enabled").get<bool>();
  p.rim.color = srgb_to_linear(vec3_of(rim.at("color")));
  p.rim.power = rim.at("power").get<float>();
  p.rim.strength = rim.at("strength").get<float>();
  p.rim.threshold = rim.at("threshold").get<float>();
  const std::string mask = rim.at("mask");
  p.rim.mask = mask == "shadow" ? RimMask::Shadow : mask == "both" ? RimMask::Both : RimMask::Lit;

  const json& halftone = j.at("halftone");
  p.halftone.enabled = halftone.at("enabled").get<bool>();
  p.halftone.style = halftone.at("style") == "checker" ? HalftoneStyle::Checker : HalftoneStyle::Dots;
  p.halftone.cell_px = halftone.at("cell").get<float>();
  p.halftone.angle_deg = halftone.at("angle").get<float>();
  p.halftone.ink = srgb_to_linear(vec3_of(halftone.at("ink")));
  p.halftone.ink_mix = halftone.at("ink_mix").get<float>();

  const json& contour = j.at("contour");
  p.contour.enabled = contour.at("enabled").get<bool>();
  p.contour.style = contour.at("style") == "fresnel" ? ContourStyle::Fresnel : ContourStyle::Even;
  p.contour.width_px = contour.at("width").get<float>();
  p.contour.threshold = contour.at("threshold").get<float>();
  p.contour.color = srgb_to_linear(vec3_of(contour.at("color")));
}

// The shadow map and the floor that receives it.
void read_ground(const json& j, RenderParams& p) {
  const json& shadows = j.at("shadows");
  p.shadows.enabled = shadows.at("enabled").get<bool>();
  p.shadows.map_size = shadows.at("map_size").get<int>();
  p.shadows.pcf = shadows.at("pcf").get<int>();
  p.shadows.bias_texels = shadows.at("bias").get<float>();

  const json& floor = j.at("floor");
  p.floor.enabled = floor.at("enabled").get<bool>();
  p.floor.color = srgb_to_linear(vec3_of(floor.at("color")));
  p.floor.size = floor.at("size").get<float>();
  p.floor.texture = floor.at("texture").get<std::string>();
  p.floor.texture_repeat = floor.at("texture_repeat").get<float>();
}

// Per-material drawing and how textures are sampled.
void read_materials(const json& j, RenderParams& p) {
  for (const auto& [name, m] : j.at("materials").items()) {
    MaterialParams& given = p.materials[name];
    if (m.contains("alpha")) {
      const std::string alpha = m.at("alpha");
      given.alpha = alpha == "mask"    ? scene::AlphaMode::Mask
                    : alpha == "blend" ? scene::AlphaMode::Blend
                                       : scene::AlphaMode::Opaque;
    }
    if (m.contains("alpha_cutoff")) given.alpha_cutoff = m.at("alpha_cutoff").get<float>();
    if (m.contains("texture")) given.texture = m.at("texture").get<std::string>();
  }
  const std::string filter = j.at("textures").at("filter");
  p.texture_filter = filter == "nearest"  ? TextureFilterChoice::Nearest
                     : filter == "linear" ? TextureFilterChoice::Linear
                                          : TextureFilterChoice::Auto;
}

void read_outline(const json& j, RenderParams& p) {
  const json& outline = j.at("outline");
  p.outline.enabled = outline.at("enabled").get<bool>();
  p.outline.width = outline.at("width").get<float>();
  p.outline.units = outline.at("units") == "world" ? OutlineUnits::World : OutlineUnits::Pixels;
  const json& method = outline.at("method");
  const json methods = method.is_array() ? method : json::array({method});
  p.outline.hull = p.outline.wireframe = p.outline.edges = false;
  for (const json& m : methods) {
    p.outline.hull |= m == "hull";
    p.outline.wireframe |= m == "wireframe";
    p.outline.edges |= m == "edges";
  }
  const std::string creases = outline.at("creases");
  p.outline.creases = creases == "always"  ? OutlineCreases::Always
                      : creases == "never" ? OutlineCreases::Never
                                           : OutlineCreases::Auto;
  p.outline.crease_angle_deg = outline.at("crease_angle").get<float>();
  p.outline.depth_threshold = outline.at("depth_threshold").get<float>();
  p.outline.color = srgb_to_linear(vec3_of(outline.at("color")));
  const std::string color_mode = outline.at("color_mode");
  p.outline.color_mode = color_mode == "texture"    ? OutlineColorMode::Texture
                         : color_mode == "material" ? OutlineColorMode::Material
                                                    : OutlineColorMode::Fixed;
  p.outline.darken = outline.at("darken").get<float>();
}

}  // namespace

RenderParams render_params_from_wire(const json& j) {
  RenderParams p;
  read_scene(j, p);
  read_camera(j, p);
  read_lights(j, p);
  read_shading(j, p);
  read_effects(j, p);
  read_ground(j, p);
  read_materials(j, p);
  read_outline(j, p);
  p.msaa = j.at("msaa").get<int>();
  p.supersample = j.at("supersample").get<int>();
  p.lod_auto = j.at("lod") == "auto";
  p.lod_error_px = j.at("lod_error_px").get<double>();
  p.png_compression = j.at("png_compression").get<int>();
  if (j.contains("sheet")) p.sheet = sheet_of(j.at("sheet"), p.camera);
  if (j.contains("animation")) p.animation = animation_of(j.at("animation"));
  p.output = output_of(j.at("output").get<std::string>());
  p.svg.hidden = j.at("svg").at("hidden").get<bool>();
  return p;
}

}  // namespace toond::pipeline
