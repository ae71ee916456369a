#include "gallery_looks.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <set>
#include <system_error>

#include "cli_args.h"
#include "param_schema.h"
#include "request_error.h"

namespace toond::cli::gallery {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// ---------------------------------------------------------------------------
// The effect looks: one render per technique, each a partial set of render
// parameters on top of the schema's defaults. This table is the only list of
// them; every entry is checked against the schema before anything is sent
// (and by the unit tests), so a renamed parameter fails with the look's name.
//
// Lights are written for the default camera (yaw 30, pitch 15: the camera
// sits front-right and a little above); render_params turns them to each
// model's view. Point light positions and radii are in bounding radii from
// the model's centre.
struct LookEntry {
  const char* name;
  const char* description;
  const char* params;  // JSON
};

constexpr LookEntry kEffectTable[] = {
    {"default", "The schema's defaults: three cel bands, hard specular, 2 px hull outline, MSAA 4.", R"({})"},
    {"specular_off", "No specular highlight: only the cel bands.", R"({"specular": {"enabled": false}})"},
    {"specular_broad", "Specular on with a broad, hard-edged highlight.",
     R"({"specular": {"enabled": true, "shininess": 16, "threshold": 0.3, "strength": 0.9}})"},
    {"rim", "Rim light on the lit side, warm, thresholded into a band.",
     R"({"rim": {"enabled": true, "color": [1, 0.92, 0.75], "power": 3, "strength": 0.7,
                 "threshold": 0.3, "mask": "lit"}})"},
    {"halftone_dots", "True screen-space halftone: dots on a 45° grid, larger where the light falls off.",
     R"({"halftone": {"enabled": true, "style": "dots", "cell": 6, "angle": 45}})"},
    {"halftone_checker", "The cheap halftone: a checker of neighbouring bands in the mid tones.",
     R"({"shading": {"steps": 4}, "halftone": {"enabled": true, "style": "checker", "cell": 4}})"},
    {"contour_even", "Contour lines of even width where N·V nears zero (no hull outline).",
     R"({"outline": {"enabled": false},
         "contour": {"enabled": true, "style": "even", "width": 1.5}})"},
    {"contour_fresnel", "Fresnel contour: N·V below a threshold, thicker where the surface turns slowly.",
     R"({"outline": {"enabled": false},
         "contour": {"enabled": true, "style": "fresnel", "threshold": 0.25}})"},
    {"shadows_floor", "Shadows from a high key light, on the model and on a floor plane.",
     R"({"shadows": {"enabled": true}, "floor": {"enabled": true, "size": 2.5},
         "lights": [{"type": "directional", "direction": [0.41, -1.76, -0.9]}]})"},
    {"two_tone", "Two-tone palette: below N·L 0.25 the diffuse is a quarter of the lit colour.",
     R"({"shading": {"two_tone": {"enabled": true, "threshold": 0.25, "shadow_factor": 0.25}}})"},
    {"color_ramp", "A colour ramp: cool violet shadow, dusky mid tone, warm light.",
     R"({"shading": {"ramp": [{"at": -1, "color": [0.34, 0.32, 0.55]},
                              {"at": 0.2, "color": [0.8, 0.72, 0.8]},
                              {"at": 0.6, "color": [1, 0.96, 0.86]}]}})"},
    {"outline_texture", "A 3 px outline coloured from the texture, inverted and darkened.",
     R"({"outline": {"width": 3, "color_mode": "texture"}})"},
    {"outline_material", "A 3 px outline in the material colour, darkened.",
     R"({"outline": {"width": 3, "color_mode": "material"}})"},
    {"supersample_2", "Rendered at twice the size and averaged down (with MSAA 4 on top).", R"({"supersample": 2})"},
    {"msaa_1", "No antialiasing: compare the edges with msaa_8.", R"({"msaa": 1})"},
    {"msaa_8", "8× multisampling.", R"({"msaa": 8})"},
    {"lights_sum", "Two coloured lights added up: a warm key from the upper left, a cool fill from the right.",
     R"({"light_combine": "sum",
         "lights": [{"type": "directional", "direction": [0.19, -0.86, -1.23],
                     "color": [1, 0.62, 0.3], "intensity": 0.8},
                    {"type": "directional", "direction": [-1.2, -0.3, -0.4],
                     "color": [0.3, 0.55, 1], "intensity": 0.8}]})"},
    {"point_light", "One point light close to the front left, fading out with distance.",
     R"({"lights": [{"type": "point", "position": [-0.6, 0.9, 1.1], "radius": 3}]})"},
    {"lines_layer",
     "The lines alone on transparent (output lines): outline, crease lines and an even contour, to ink over or "
     "recolour.",
     R"({"output": "lines", "contour": {"enabled": true, "style": "even", "width": 1.5}})"},
    {"sprite_sheet",
     "An 8-direction sprite sheet, 4 tiles across, one framing for every frame; the atlas is in the PNG's tEXt "
     "chunk toond:atlas.",
     R"({"sheet": {"frames": 8, "columns": 4}})"},
};

// Views by model folder (the shared models' names); every other folder gets
// the schema's default camera, front-right and a little above. Spot and Bob
// face -Z, so they are seen from behind the origin; Blub lies along Z and
// the windmill's sails face +X, so both are turned to a three-quarter view.
struct ViewEntry {
  const char* folder;
  double yaw;
  double pitch;
};
constexpr ViewEntry kViewTable[] = {
    {"spot", -140, 12},
    {"bob", -140, 12},
    {"blub", 60, 15},
    {"windmill", 65, 8},
};

// The space craft is the hard-edged one: its default look shows crease
// lines. Bob comes as glTF: textured, with normals and UVs, it takes the
// glTF path through the daemon's importer the way a downloaded .glb does.
const std::vector<std::string> kDefaultModels = {
    "spot", "kenney-cube-pet-dog", "kenney-space-craft", "windmill", "stanford-bunny", "utah-teapot", "bob.glb"};

constexpr std::string_view kGlbSuffix = ".glb";

double schema_default(const proto::ParamSchema& schema, const char* field, double fallback) {
  const json& d = schema.document();
  const json* node = &d;
  for (const char* key : {"properties", "camera", "properties", field, "default"}) {
    if (!node->is_object() || !node->contains(key)) return fallback;
    node = &(*node)[key];
  }
  return node->is_number() ? node->get<double>() : fallback;
}

json default_lights(const proto::ParamSchema& schema) {
  const json& d = schema.document();
  if (d.contains("properties") && d["properties"].contains("lights") && d["properties"]["lights"].contains("default")) {
    return d["properties"]["lights"]["default"];
  }
  return json::array({{{"type", "directional"}, {"direction", {-0.4, -0.5, -1}}}});
}

// Three decimals are plenty for a light and keep the JSON and the command short.
double tidy(double v) {
  const double r = std::round(v * 1000.0) / 1000.0;
  return r == 0 ? 0.0 : r;  // no "-0.0"
}

// `v` rounded to a ten-thousandth of `scale` (a power of ten), for
// positions: models range from millimetres to kilometres across.
double tidy_to(double v, double scale) {
  if (!(scale > 0) || !std::isfinite(scale)) return v;
  const int e = static_cast<int>(std::floor(std::log10(scale))) - 4;
  // Dividing by an exact power of ten prints shortest ("0.5176", not "0.5176000000000001").
  const double r = e < 0 ? std::round(v * std::pow(10.0, -e)) / std::pow(10.0, -e)
                         : std::round(v / std::pow(10.0, e)) * std::pow(10.0, e);
  return r == 0 ? 0.0 : r;
}

// Turns (x, z) about the vertical axis the way the camera's yaw does: by
// `degrees`, (0, 0, 1) goes to (sin, 0, cos).
void turn(double& x, double& z, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  const double nx = x * c + z * s;
  const double nz = -x * s + z * c;
  x = nx;
  z = nz;
}

json place_lights(const json& lights, double yaw_delta, const ModelFrame& frame, bool relative_points) {
  json out = json::array();
  for (json light : lights) {
    if (light.contains("direction") && light["direction"].is_array() && light["direction"].size() == 3) {
      double x = light["direction"][0].get<double>();
      const double y = light["direction"][1].get<double>();
      double z = light["direction"][2].get<double>();
      turn(x, z, yaw_delta);
      light["direction"] = {tidy(x), tidy(y), tidy(z)};
    }
    if (light.contains("position") && light["position"].is_array() && light["position"].size() == 3) {
      double p[3];
      for (int i = 0; i < 3; ++i) p[i] = light["position"][static_cast<std::size_t>(i)].get<double>();
      if (relative_points) {
        for (double& v : p) v *= frame.radius;
      } else {
        for (int i = 0; i < 3; ++i) p[i] -= frame.center[i];
      }
      turn(p[0], p[2], yaw_delta);
      light["position"] = {tidy_to(p[0] + frame.center[0], frame.radius), tidy_to(p[1] + frame.center[1], frame.radius),
                           tidy_to(p[2] + frame.center[2], frame.radius)};
      if (relative_points && light.contains("radius") && light["radius"].is_number()) {
        light["radius"] = tidy_to(light["radius"].get<double>() * frame.radius, frame.radius);
      }
    }
    out.push_back(std::move(light));
  }
  return out;
}

// --set pairs for `value` at `dotted`: objects by their leaves, the rest as text.
void flatten_into(std::vector<std::pair<std::string, std::string>>& out, const std::string& dotted, const json& value) {
  if (value.is_object() && !value.empty()) {
    for (const auto& [key, child] : value.items()) flatten_into(out, dotted + "." + key, child);
  } else if (value.is_string()) {
    out.emplace_back(dotted, value.get<std::string>());
  } else {
    out.emplace_back(dotted, value.dump());
  }
}

bool has_point_light(const json& lights) {
  return std::any_of(lights.begin(), lights.end(),
                     [](const json& l) { return l.is_object() && l.value("type", "") == "point"; });
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The .obj files directly inside `dir`, by name.
std::vector<fs::path> obj_files_in(const fs::path& dir) {
  std::vector<fs::path> objs;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code type_ec;
    if (it->is_regular_file(type_ec) && lower(it->path().extension().string()) == ".obj") {
      objs.push_back(it->path());
    }
  }
  std::sort(objs.begin(), objs.end());
  return objs;
}

std::string why_not_one_obj(const std::vector<fs::path>& objs) {
  if (objs.empty()) return "no .obj directly inside";
  return std::to_string(objs.size()) + " .obj files (the gallery needs exactly one)";
}

// The model `name` stands for in `dir`: its folder, or for FOLDER.glb with
// no folder of that name, FOLDER's OBJ as a .glb. Empty `why` when found.
ModelFolder find_model(const fs::path& dir, const std::string& name, std::string& why) {
  std::error_code ec;
  ModelFolder model{name, {}, name, false};
  if (!fs::is_directory(dir / name, ec) && name.size() > kGlbSuffix.size() && name.ends_with(kGlbSuffix)) {
    model.folder = name.substr(0, name.size() - kGlbSuffix.size());
    model.as_glb = true;
  }
  if (!fs::is_directory(dir / model.folder, ec)) {
    why = "not found in " + dir.string();
    return model;
  }
  const auto objs = obj_files_in(dir / model.folder);
  if (objs.size() != 1) {
    why = why_not_one_obj(objs);
    return model;
  }
  model.obj_path = objs.front();
  why.clear();
  return model;
}

}  // namespace

const std::vector<Look>& effect_looks() {
  static const std::vector<Look> looks = [] {
    std::vector<Look> out;
    for (const LookEntry& e : kEffectTable) {
      out.push_back(Look{e.name, e.description, json::parse(e.params), false});
    }
    return out;
  }();
  return looks;
}

std::vector<Look> preset_looks(const json& presets, const proto::ParamSchema& schema) {
  std::vector<std::string> order;
  const json& d = schema.document();
  if (d.contains("properties") && d["properties"].contains("preset") && d["properties"]["preset"].contains("enum")) {
    for (const json& name : d["properties"]["preset"]["enum"]) order.push_back(name.get<std::string>());
  }
  std::vector<Look> looks;
  if (!presets.is_object()) return looks;
  for (const auto& [name, entry] : presets.items()) {
    std::string description;
    if (entry.is_object() && entry.contains("description") && entry["description"].is_string()) {
      description = entry["description"].get<std::string>();
    }
    looks.push_back(Look{name, description, json{{"preset", name}}, true});
  }
  const auto rank = [&](const Look& l) {
    return static_cast<std::size_t>(std::find(order.begin(), order.end(), l.name) - order.begin());
  };
  std::stable_sort(looks.begin(), looks.end(), [&](const Look& a, const Look& b) {
    const auto ra = rank(a), rb = rank(b);
    return ra != rb ? ra < rb : a.name < b.name;
  });
  return looks;
}

void validate_look(const Look& look, const proto::ParamSchema& schema) {
  try {
    schema.validate(look.params);
  } catch (const RequestError& e) {
    std::string message = "gallery look '" + look.name + "' does not fit the render schema: " + e.what();
    if (!e.path().empty() && std::string(e.what()).find(e.path()) == std::string::npos) {
      message += " (at " + e.path() + ")";
    }
    message += look.is_preset ? "; this toon does not know the daemon's preset (rebuild toon?)"
                              : "; the look table is in client/cli/gallery_looks.cpp";
    throw UsageError(message);
  }
}

ModelView view_for_model(std::string_view folder, const proto::ParamSchema& schema) {
  ModelView view{schema_default(schema, "yaw", 30), schema_default(schema, "pitch", 15)};
  for (const ViewEntry& e : kViewTable) {
    if (folder == e.folder) return ModelView{e.yaw, e.pitch};
  }
  return view;
}

ModelFrame frame_from_obj(std::string_view text) {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any = false;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
    line.remove_prefix(2);
    double v[3];
    int n = 0;
    while (n < 3) {
      while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
      if (line.empty()) break;
      const auto [next, ec] = std::from_chars(line.data(), line.data() + line.size(), v[n]);
      if (ec != std::errc() || !std::isfinite(v[n])) break;
      line.remove_prefix(static_cast<std::size_t>(next - line.data()));
      ++n;
    }
    if (n < 3) continue;
    for (int i = 0; i < 3; ++i) {
      lo[i] = any ? std::min(lo[i], v[i]) : v[i];
      hi[i] = any ? std::max(hi[i], v[i]) : v[i];
    }
    any = true;
  }
  ModelFrame frame;
  if (!any) return frame;
  double r2 = 0;
  for (int i = 0; i < 3; ++i) {
    frame.center[i] = (lo[i] + hi[i]) / 2;
    r2 += (hi[i] - lo[i]) * (hi[i] - lo[i]) / 4;
  }
  frame.radius = r2 > 0 ? std::sqrt(r2) : 1.0;
  return frame;
}

json render_params(const Look& look, const json& preset_params, const ModelView& view, const ModelFrame& frame,
                   int size, const std::string& model_id, const proto::ParamSchema& schema) {
  json params = look.params;
  params["width"] = size;
  params["height"] = size;

  const double default_yaw = schema_default(schema, "yaw", 30);
  const double default_pitch = schema_default(schema, "pitch", 15);
  if (view.yaw != default_yaw || view.pitch != default_pitch) {
    json camera = {{"yaw", view.yaw}, {"pitch", view.pitch}};
    if (params.contains("camera") && params["camera"].is_object()) camera.update(params["camera"]);
    params["camera"] = camera;
  }

  // The lights this render would get without us, and whose units they use.
  json lights;
  bool relative_points = false;
  if (params.contains("lights")) {
    lights = params["lights"];
    relative_points = !look.is_preset;
  } else if (preset_params.is_object() && preset_params.contains("lights")) {
    lights = preset_params["lights"];
  } else {
    lights = default_lights(schema);
  }
  // A sheet's lights turn with its camera already (lights[].space view is
  // a sheet's default): turning them here too would light it from behind.
  const double yaw_delta = params.contains("sheet") ? 0.0 : view.yaw - default_yaw;
  if (lights.is_array() && (yaw_delta != 0 || (relative_points && has_point_light(lights)))) {
    params["lights"] = place_lights(lights, yaw_delta, frame, relative_points);
  }

  if (!model_id.empty()) params["model"] = model_id;
  return params;
}

std::string shell_quote(std::string_view text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("_.,/:=+@%-").find(c) != std::string_view::npos;
  });
  if (plain) return std::string(text);
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  out += '\'';
  return out;
}

std::vector<std::pair<std::string, std::string>> set_arguments(const json& params) {
  std::vector<std::pair<std::string, std::string>> out;
  if (params.is_object()) {
    for (const auto& [key, value] : params.items()) {
      if (key != "model") flatten_into(out, key, value);
    }
  }
  return out;
}

std::string render_command(const std::string& obj_path, const json& params, const std::string& output) {
  std::string command = "toon render " + shell_quote(obj_path);
  for (const auto& [key, value] : set_arguments(params)) {
    command += " --set " + shell_quote(key + "=" + value);
  }
  command += " -o " + shell_quote(output);
  return command;
}

const std::vector<std::string>& default_model_names() { return kDefaultModels; }

ModelSelection select_models(const fs::path& dir, bool all, const std::vector<std::string>& only) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw UsageError("--models " + dir.string() + ": not a folder (give the folder of model folders)");
  }
  ModelSelection selection;
  std::string why;
  if (!only.empty()) {
    std::set<std::string> seen;
    for (const std::string& name : only) {
      if (!seen.insert(name).second) throw UsageError("--only names " + name + " twice");
      ModelFolder model = find_model(dir, name, why);
      if (!why.empty()) throw UsageError("--only " + name + ": " + why);
      selection.models.push_back(std::move(model));
    }
    return selection;
  }

  std::vector<std::string> names;
  if (all) {
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      std::error_code type_ec;
      if (it->is_directory(type_ec)) names.push_back(it->path().filename().string());
    }
    std::sort(names.begin(), names.end());
    // The glTF model too, where its folder is here (one more row, not a note).
    for (const std::string& name : kDefaultModels) {
      const bool folder_here =
          name.ends_with(kGlbSuffix) &&
          std::find(names.begin(), names.end(), name.substr(0, name.size() - kGlbSuffix.size())) != names.end();
      if (folder_here && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  } else {
    names = kDefaultModels;
  }
  for (const std::string& name : names) {
    ModelFolder model = find_model(dir, name, why);
    if (!why.empty()) {
      selection.notes.push_back("skipping " + name + ": " + why);
      continue;
    }
    selection.models.push_back(std::move(model));
  }
  if (selection.models.empty()) {
    throw UsageError("no model folder to render in " + dir.string() +
                     (all ? " (each needs exactly one .obj directly inside)"
                          : " (none of the default models; try --all or --only NAME)"));
  }
  return selection;
}

}  // namespace toond::cli::gallery
