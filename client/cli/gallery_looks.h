#pragma once
// What `toon gallery` renders: the looks (every preset the daemon offers,
// plus one look per effect from the table in gallery_looks.cpp), the models
// (folders of a models directory, each with a per-model view), and the exact
// render parameters for one (model, look) pair. No network code, so every
// rule here is unit-tested without a daemon.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace toond::proto {
class ParamSchema;
}

namespace toond::cli::gallery {

struct Look {
  std::string name;         // file name (name.png) and column title: [a-z0-9_]
  std::string description;  // one line for the index page
  nlohmann::json params;    // the look's parameters: {"preset": name} or an effect overlay
  bool is_preset = false;
};

// The effect looks, from the one table of them, in gallery order. Lights in
// the table are written for the schema's default camera; point light
// positions and radii are in units of the model's bounding radius, measured
// from its centre (see render_params).
const std::vector<Look>& effect_looks();

// One look per preset of a GET /presets answer ({"name": {"description",
// "params"}, ...}), in the order of the schema's preset enum (names the
// schema does not list come last, alphabetically).
std::vector<Look> preset_looks(const nlohmann::json& presets, const proto::ParamSchema& schema);

// Throws UsageError naming the look and the field when the look's parameters
// do not validate against the schema (a parameter renamed since the table was
// written, a preset this toon does not know).
void validate_look(const Look& look, const proto::ParamSchema& schema);

// How a model is looked at: the camera's yaw and pitch, degrees.
struct ModelView {
  double yaw = 30;
  double pitch = 15;
};
// The view for a model folder from the gallery's table (Spot faces -Z, so it
// is seen from behind the origin); the schema's default camera otherwise.
ModelView view_for_model(std::string_view folder, const proto::ParamSchema& schema);

// Centre and bounding radius of an OBJ's `v` lines (centre 0, radius 1 when
// it has none); used to place the point lights of effect looks.
struct ModelFrame {
  double center[3] = {0, 0, 0};
  double radius = 1;
};
ModelFrame frame_from_obj(std::string_view obj_text);

// The request body for one render. The look's parameters come first; width
// and height are `size`; the camera is the model's view where that differs
// from the default. The lights the render would use (the look's, else its
// preset's, else the schema's default) are turned about the vertical axis
// by the difference between the model's yaw and the default yaw, so each
// model is lit from the side the camera sees, as the default camera is; the
// effect table's point lights are scaled to the model. `preset_params` is
// the preset's own parameters (null for an effect look). `model_id` empty
// leaves "model" out.
nlohmann::json render_params(const Look& look, const nlohmann::json& preset_params, const ModelView& view,
                             const ModelFrame& frame, int size, const std::string& model_id,
                             const proto::ParamSchema& schema);

// `toon render OBJ --set key=value ... -o OUT` reproducing `params` (without
// its "model"), with shell quoting where a value needs it.
std::string render_command(const std::string& obj_path, const nlohmann::json& params, const std::string& output);
// The --set pairs of render_command, in order; objects become dotted keys,
// arrays and numbers their JSON text, strings their text.
std::vector<std::pair<std::string, std::string>> set_arguments(const nlohmann::json& params);
// `text` single-quoted for a POSIX shell when it holds anything but
// letters, digits and _ . , / : = + @ % -.
std::string shell_quote(std::string_view text);

// Model folders for the gallery. A name FOLDER.glb, where no folder has
// that name, is FOLDER's OBJ sent as the .glb toon writes from it
// (glb_from_obj.h): the shared models are all OBJ, and the gallery shows a
// glTF model too.
struct ModelFolder {
  std::string name;                // the folder's name, or FOLDER.glb
  std::filesystem::path obj_path;  // the one .obj directly inside the folder
  std::string folder;              // the folder's name (its view: view_for_model)
  bool as_glb = false;             // sent as the .glb written from obj_path
};
struct ModelSelection {
  std::vector<ModelFolder> models;
  std::vector<std::string> notes;  // folders skipped and why, for stderr
};
// The folders the gallery renders when neither --all nor --only is given.
const std::vector<std::string>& default_model_names();
// `only` non-empty: exactly those names, in that order (a missing folder,
// or one without exactly one .obj, is a UsageError). `all`: every folder of
// `dir` with exactly one .obj directly inside, by name, then the default
// FOLDER.glb names whose folder is there; the rest are noted. Neither: the
// default names that are present. Throws UsageError when `dir` is not a
// folder or nothing is left to render.
ModelSelection select_models(const std::filesystem::path& dir, bool all, const std::vector<std::string>& only);

}  // namespace toond::cli::gallery
