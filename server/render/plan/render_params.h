#pragma once
// Render parameters as the renderer uses them: resolved and typed. The
// pipeline builds them from a request that ParamSchema::validate_and_complete()
// has checked and filled with the schema's defaults
// (pipeline/render_params_wire.h), so every field is present and in range here;
// names and defaults live in proto/render-params.schema.json, not in this
// file.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/animation/clip_sampling.h"
#include "scene/mesh/model.h"

namespace toond::render {

// sRGB transfer function, for colours given in the wire format.
float srgb_to_linear(float c);
glm::vec3 srgb_to_linear(const glm::vec3& c);

// The members' initial values are the schema's defaults (colours as the
// schema writes them, made linear); RenderParamsDefaults checks each.
enum class ShadingMode { Cel, Phong, Flat };
enum class BaseColor { Material, White };
// What the answer holds: the finished colour, the lines alone, one of the
// data layers a compositor uses, or the lines as vector paths (proto schema
// `output`).
enum class Output { Color, Lines, Depth, Normal, Id, Svg };
enum class Rounding { Ceil, Floor, Round };
enum class Projection { Perspective, Orthographic };

struct CameraParams {
  Projection projection = Projection::Perspective;
  double yaw_deg = 30;
  double pitch_deg = 15;
  double fov_deg = 35;
  double distance = 0;    // 0: fit to the model's bounds
  double zoom = 1;        // divides the fitted distance or frame; ignored with distance set
  glm::dvec2 shift{0.0};  // eye and target moved along view right/up, in bounding radii
  // Not on the wire: more views, as (yaw, pitch) in degrees, that a fitted
  // distance or orthographic frame must also hold. A sprite sheet lists all
  // its frames here, so each frame is framed alike and the model keeps its
  // size and place from one to the next. Empty: the camera's own view only.
  std::vector<glm::dvec2> framed_views;
};

// The `animation` block: a clip by name (`clip`) or by index
// (`clip_index` >= 0), at `time` seconds of its loop: of `range` when one
// is given (time counted from its start), else of the whole clip.
struct AnimationParams {
  std::string clip;
  int clip_index = -1;
  double time = 0;
  std::optional<scene::ClipRange> range;  // seconds on the file's time base, as asked
};

// One clip of an animated sheet (`sheet.animation`): as asked, then, once
// the pipeline has looked it up in the model, resolved.
struct SheetClip {
  std::string clip;     // by name; or
  int clip_index = -1;  // by index (>= 0)
  std::optional<int> frames;
  std::optional<double> fps;
  std::optional<scene::ClipRange> range;  // as asked; unset: the whole clip
  // A loop leaves its end out (it is its start again); a one-shot (false)
  // puts frames on both ends, its last pose included.
  bool loop = true;
  // Resolved (pipeline/clips.h):
  std::size_t index = 0;  // into the model's Rig::clips
  std::string name;
  scene::ClipRange span;  // what the row plays: `range`, or the whole clip
  double duration = 0;    // span's length, seconds
  int frame_count = 0;    // columns of its rows
};

// A sprite sheet (the `sheet` block), with every absent field resolved:
// frames at yaw_start + i × yaw_step, for each pitch in turn.
struct SheetParams {
  int frames = 8;
  int columns = 8;                  // absent on the wire: `frames`, one row per pitch
  double yaw_start_deg = 0;         // absent: the camera's yaw
  double yaw_step_deg = 45;         // absent: 360 / frames
  std::vector<double> pitches_deg;  // absent: the camera's pitch alone
  int padding = 0;                  // pixels between neighbouring tiles
  // Pixel art (`sheet.pixel_art`): tiles drawn at 1/scale, quantised to one
  // palette for the whole sheet, blown up by `scale`. Unset: tiles as drawn.
  struct PixelArt {
    int scale = 4;    // width and height are multiples of it (checked by the pipeline, sheet_checks.h)
    int colors = 16;  // size of the computed palette when `palette` is empty
    std::vector<std::array<std::uint8_t, 3>> palette;  // sRGB; empty: computed over the sheet
    bool dither = false;                               // ordered 4×4 Bayer dithering
    // sprite: 1-art-pixel outline, only readable inner lines, no contour;
    // as_given: the request's line settings as they are.
    enum class Lines { Sprite, AsGiven } lines = Lines::Sprite;
  };
  std::optional<PixelArt> pixel_art;
  bool animate = false;  // answer an animated WebP of the frames instead of the sheet's PNG
  // `sheet.pack`: each tile cut to its visible pixels and packed, `padding`
  // apart (pipeline/sheet_answer.h); `power_of_two`: the packed sheet's
  // sides powers of two.
  bool pack = false;
  bool power_of_two = false;
  // `sheet.layers`: the layers every frame is drawn as (color, lines), as
  // listed (pipeline/sheet_layers.h). Empty: the output alone, as asked.
  std::vector<Output> layers;
  int frame_ms = 100;  // how long each animation frame shows
  // An animated sheet: per clip, per pitch, a row per direction (`frames`
  // yaws) of the clip's frames. Empty: a turntable.
  std::vector<SheetClip> clips;
  bool clip_list = false;  // sheet.animation was a list (error paths name the entry)
};

enum class LightKind { Directional, Point };
// Model: direction and position in the scene's coordinates (a lone model's
// own); the light stays put while the camera turns. View: along the
// camera's axes (x right, y up, z toward the viewer), a position as an
// offset from the point the camera orbits; the light turns with the camera
// (render/plan/light_space.h).
enum class LightSpace { Model, View };
enum class LightCombine { Max, Sum };
enum class RimMask { Lit, Shadow, Both };
enum class HalftoneStyle { Dots, Checker };
enum class ContourStyle { Even, Fresnel };

struct Light {
  LightKind kind = LightKind::Directional;
  glm::dvec3 direction{0, 0, -1};  // directional: the way the light travels
  glm::dvec3 position{0.0};        // point: in model coordinates
  double radius = 0;               // point: reach in model units, 0 = unlimited
  glm::vec3 color{1.0f};           // linear, intensity applied
  LightSpace space = LightSpace::Model;
};

// Which materials get the highlight: those whose file gives them one
// (scene::Material::matte is false), or every one.
enum class SpecularSource { Material, All };

struct SpecularParams {
  SpecularSource source = SpecularSource::Material;
  bool enabled = true;
  glm::vec3 color{1.0f};  // linear
  float shininess = 48;
  float threshold = 0.5f;
  float strength = 0.8f;
};

struct RimParams {
  bool enabled = false;
  glm::vec3 color{1.0f};  // linear
  float power = 3;
  float strength = 0.6f;
  float threshold = 0.18f;
  RimMask mask = RimMask::Shadow;
};

struct HalftoneParams {
  bool enabled = false;
  HalftoneStyle style = HalftoneStyle::Dots;
  float cell_px = 8;
  float angle_deg = 45;
  glm::vec3 ink{0.0f};  // linear
  float ink_mix = 0;
};

struct ContourParams {
  bool enabled = false;
  ContourStyle style = ContourStyle::Even;
  float width_px = 1.5f;
  float threshold = 0.2f;
  glm::vec3 color = srgb_to_linear(glm::vec3(0.06f, 0.05f, 0.08f));  // linear
};

struct ShadowParams {
  bool enabled = false;
  int map_size = 2048;
  int pcf = 1;
  float bias_texels = 1.5f;
};

struct FloorParams {
  bool enabled = false;
  glm::vec3 color = srgb_to_linear(glm::vec3(0.85f, 0.85f, 0.82f));  // linear
  float size = 4;                                                    // half side, in bounding radii
  std::string texture;                                               // bundle path; empty: plain colour
  float texture_repeat = 4;
  // The decoded `texture`, filled by the pipeline (which reads bundles)
  // before the job reaches the render thread; null for a plain floor.
  std::shared_ptr<const scene::Texture> image;
};

// A request's word on one material (`materials.<name>`); unset: as the
// file and its format say.
struct MaterialParams {
  std::optional<scene::AlphaMode> alpha;
  std::optional<float> alpha_cutoff;
  std::string texture;  // bundle path; empty: the material's own
  // The decoded `texture`, filled by the pipeline before the job reaches
  // the render thread.
  std::shared_ptr<const scene::Texture> image;
};

// `textures.filter`: magnification as the file says, else nearest for
// small textures (Auto); or one filter for all.
enum class TextureFilterChoice { Auto, Nearest, Linear };

enum class OutlineColorMode { Fixed, Texture, Material };

enum class OutlineUnits { Pixels, World };

// When crease lines join a hull or wireframe outline.
enum class OutlineCreases { Auto, Always, Never };

struct OutlineParams {
  bool enabled = true;
  bool hull = true;
  bool wireframe = false;
  bool edges = false;
  float width = 2;  // in `units`
  OutlineUnits units = OutlineUnits::Pixels;
  glm::vec3 color = srgb_to_linear(glm::vec3(0.06f, 0.05f, 0.08f));  // linear
  OutlineColorMode color_mode = OutlineColorMode::Fixed;
  float darken = 0.6f;
  OutlineCreases creases = OutlineCreases::Auto;
  float crease_angle_deg = 40;
  float depth_threshold = 0.02f;  // fraction of the model's size
  // Crease lines and the edges method's inner lines only between areas at
  // least this many pixels across on both sides; 0: wherever they are.
  // Not on the wire: pixel-art sprites set it (pixel_art_frame.h).
  int readable_area_px = 0;
  // Screen-space lines as whole pixels (one after each edge along each
  // axis, fully covered) instead of the share of each pixel the line
  // covers. Not on the wire: pixel-art sprites set it.
  bool whole_pixel_lines = false;
  // Crease lines found by the screen-space edge pass instead of drawn along
  // the crease edges. Not on the wire: pixel-art sprites set it (their
  // rules read the pixels on both sides of a line), and tests compare the
  // two.
  bool screen_space_creases = false;
  bool any() const { return enabled && width > 0.0f && (hull || wireframe || edges); }
};

// `output: "svg"`'s own choices (render/vector/line_drawing.h).
struct SvgParams {
  bool hidden = false;  // a dashed `hidden` layer with the lines' hidden parts
};

struct TwoToneParams {
  bool enabled = false;
  float threshold = 0.25f;
  float shadow_factor = 0.25f;
};

// One step of a lighting ramp: from N·L = at on, the diffuse is `color`.
struct RampStop {
  float at = 0;
  glm::vec3 color{1.0f};  // linear; a grey ramp's value v is (v, v, v)
};

// One object of a scene: a stored model placed by scale, then rotation
// about X, then Y, then Z (degrees), then translation.
struct SceneObject {
  std::string model;
  glm::dvec3 translate{0.0};
  glm::dvec3 rotate_deg{0.0};
  glm::dvec3 scale{1.0};
  // Model coordinates → scene coordinates, in double precision.
  glm::dmat4 matrix() const;
};

struct RenderParams {
  std::string model;                 // empty: the demo model (or the scene's objects)
  std::vector<SceneObject> objects;  // empty: `model` alone, untransformed
  int width = 512;
  int height = 512;
  glm::vec4 background{srgb_to_linear(glm::vec3(0.92f, 0.92f, 0.94f)), 1.0f};  // linear rgb, alpha
  CameraParams camera;
  std::vector<Light> lights;
  LightCombine light_combine = LightCombine::Max;
  float ambient = 0.3f;
  ShadingMode mode = ShadingMode::Cel;
  BaseColor base = BaseColor::Material;
  int steps = 3;
  Rounding rounding = Rounding::Ceil;
  bool band_aa = true;  // blend band edges across a pixel
  TwoToneParams two_tone;
  std::vector<RampStop> ramp;  // sorted by `at`; empty: bands
  // Bundle path of a ramp image; the pipeline turns it into `ramp` stops
  // (ramp_from_image) before the job is queued.
  std::string ramp_image;
  std::map<std::string, glm::vec3> shade_colors;  // material name → linear shade colour
  SpecularParams specular;
  std::map<std::string, MaterialParams> materials;  // by material name
  TextureFilterChoice texture_filter = TextureFilterChoice::Auto;
  RimParams rim;
  HalftoneParams halftone;
  ContourParams contour;
  ShadowParams shadows;
  FloorParams floor;
  OutlineParams outline;
  int msaa = 4;
  int supersample = 1;
  bool lod_auto = true;                      // false: `lod` "full", every triangle
  double lod_error_px = 0.5;                 // the most a level's error may project to, output pixels
  int png_compression = 3;                   // zlib level of the answer
  std::optional<SheetParams> sheet;          // unset: one image
  std::optional<AnimationParams> animation;  // unset: the rest pose
  Output output = Output::Color;
  SvgParams svg;
};

}  // namespace toond::render
