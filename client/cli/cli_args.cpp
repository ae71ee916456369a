#include "cli_args.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "param_schema.h"
#include "request_error.h"

namespace toond::cli {
namespace {

using nlohmann::json;

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

bool is_index(std::string_view s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// One value-taking option as the user may write it: `--name value` or
// `--name=value`.
class ArgCursor {
 public:
  explicit ArgCursor(const std::vector<std::string>& args) : args_(args) {}
  bool done() const { return i_ >= args_.size(); }
  const std::string& current() const { return args_[i_]; }
  void next() { ++i_; }

  // True when the current argument is `name` (taking the next argument as
  // its value) or `name=value`.
  bool take(std::string_view name, std::string& value) {
    const std::string& a = args_[i_];
    if (a == name) {
      if (i_ + 1 >= args_.size()) throw UsageError(std::string(name) + " needs a value");
      value = args_[++i_];
      return true;
    }
    if (a.size() > name.size() && a.compare(0, name.size(), name) == 0 && a[name.size()] == '=') {
      value = a.substr(name.size() + 1);
      return true;
    }
    return false;
  }

 private:
  const std::vector<std::string>& args_;
  std::size_t i_ = 0;
};

void set_once(std::optional<std::string>& slot, std::string value, std::string_view flag) {
  if (slot) throw UsageError(std::string(flag) + " given twice");
  slot = std::move(value);
}

Verb verb_from_name(std::string_view name) {
  if (name == "health") return Verb::health;
  if (name == "upload") return Verb::upload;
  if (name == "render") return Verb::render;
  if (name == "gallery") return Verb::gallery;
  throw UsageError("unknown command '" + std::string(name) +
                   "' (commands: health, upload, render, gallery; see toon --help)");
}

std::string read_params_text(const std::string& file) {
  std::ostringstream ss;
  if (file == "-") {
    ss << std::cin.rdbuf();
    return ss.str();
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UsageError("cannot read --params file " + file + ": " + std::strerror(errno));
  ss << in.rdbuf();
  return ss.str();
}

// nlohmann's messages start with "[json.exception.parse_error.101] ", which
// says nothing to someone fixing a file by hand.
std::string plain_json_error(const std::string& what) {
  if (!what.empty() && what.front() == '[') {
    if (auto close = what.find("] "); close != std::string::npos) return what.substr(close + 2);
  }
  return what;
}

// Which verbs take a verb-specific flag.
bool flag_allowed(std::string_view flag, Verb verb) {
  if (flag == "--quiet") return verb == Verb::upload;
  if (flag == "-o") return verb == Verb::render || verb == Verb::gallery;
  if (flag == "--models" || flag == "--size" || flag == "--all" || flag == "--only") {
    return verb == Verb::gallery;
  }
  return verb == Verb::render;  // --model, --params, --set
}

int parse_size(const std::string& text) {
  const bool digits = is_index(text) && text.size() <= 5;
  const long value = digits ? std::strtol(text.c_str(), nullptr, 10) : 0;
  if (!digits || value < 16 || value > 4096) {
    throw UsageError("--size '" + text + "': expected a whole number of pixels from 16 to 4096");
  }
  return static_cast<int>(value);
}

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string name = text.substr(start, comma - start);
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
      throw UsageError("--only '" + text + "': expected model folder names separated by commas");
    }
    names.push_back(std::move(name));
    start = comma + 1;
  }
  return names;
}

}  // namespace

std::string_view verb_name(Verb verb) {
  switch (verb) {
    case Verb::health: return "health";
    case Verb::upload: return "upload";
    case Verb::render: return "render";
    case Verb::gallery: return "gallery";
    case Verb::none: break;
  }
  return "";
}

ServerUrl parse_server_url(std::string_view url) {
  std::string_view rest;
  std::string scheme;
  for (std::string_view s : {"http://", "https://"}) {
    if (url.size() > s.size() && iequals(url.substr(0, s.size()), s)) {
      scheme = std::string(s);
      rest = url.substr(s.size());
      break;
    }
  }
  // Appending rather than "'" + ... sidesteps GCC 12's false -Wrestrict
  // on string concatenation at -O3.
  std::string quoted(1, '\'');
  quoted.append(url).push_back('\'');
  if (scheme.empty()) {
    throw UsageError("--server " + quoted + ": expected http://HOST[:PORT] or https://HOST[:PORT]");
  }
  if (rest.find_first_of("?#") != std::string_view::npos) {
    throw UsageError("--server " + quoted + ": a query or fragment has no meaning here");
  }
  const std::size_t slash = rest.find('/');
  const std::string_view authority = rest.substr(0, slash);
  std::string_view path = slash == std::string_view::npos ? std::string_view{} : rest.substr(slash);
  while (!path.empty() && path.back() == '/') path.remove_suffix(1);

  // The port is what follows the last ':' outside an IPv6 literal's brackets.
  const std::size_t bracket = authority.rfind(']');
  const std::size_t colon = authority.rfind(':');
  std::string_view host = authority;
  if (colon != std::string_view::npos && (bracket == std::string_view::npos || colon > bracket)) {
    host = authority.substr(0, colon);
    const std::string_view port = authority.substr(colon + 1);
    const bool digits = is_index(port) && port.size() <= 5;
    if (!digits || std::strtoul(std::string(port).c_str(), nullptr, 10) > 65535 ||
        std::strtoul(std::string(port).c_str(), nullptr, 10) == 0) {
      throw UsageError("--server " + quoted + ": bad port '" + std::string(port) + "'");
    }
  }
  if (host.empty() || host == "[]") throw UsageError("--server " + quoted + ": no host");
  if (authority.find('@') != std::string_view::npos) {
    throw UsageError("--server " + quoted + ": user names in the URL are not supported");
  }
  return ServerUrl{scheme + std::string(authority), std::string(path)};
}

std::optional<std::string> server_from_environment() {
  const char* value = std::getenv("TOOND_URL");
  if (!value || !*value) return std::nullopt;
  return std::string(value);
}

Options parse_args(const std::vector<std::string>& args,
                   const std::optional<std::string>& env_server) {
  Options o;
  std::optional<std::string> server, model, params, output, models_dir, size;
  std::vector<std::string> positionals;
  std::vector<std::string> seen_flags;  // verb-specific ones, to check against the verb later
  bool verb_seen = false;
  bool help_verb = false;  // `toon help render`
  bool options_ended = false;

  for (ArgCursor c(args); !c.done(); c.next()) {
    const std::string& a = c.current();
    const bool looks_like_flag = !options_ended && a.size() > 1 && a[0] == '-';
    if (!looks_like_flag) {
      if (!verb_seen) {
        verb_seen = true;
        if (a == "help") {
          help_verb = true;
          o.help = true;
        } else {
          o.verb = verb_from_name(a);
        }
      } else if (help_verb && o.verb == Verb::none) {
        o.verb = verb_from_name(a);
      } else {
        positionals.push_back(a);
      }
      continue;
    }
    std::string value;
    if (a == "--") {
      options_ended = true;
    } else if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--version") {
      o.version = true;
    } else if (c.take("--server", value)) {
      set_once(server, value, "--server");
    } else if (a == "-q" || a == "--quiet") {
      o.quiet = true;
      seen_flags.push_back("--quiet");
    } else if (c.take("--model", value)) {
      if (value.empty()) throw UsageError("--model needs a model id");
      set_once(model, value, "--model");
      seen_flags.push_back("--model");
    } else if (c.take("--params", value)) {
      if (value.empty()) throw UsageError("--params needs a file name");
      set_once(params, value, "--params");
      seen_flags.push_back("--params");
    } else if (c.take("--set", value)) {
      const std::size_t eq = value.find('=');
      if (eq == std::string::npos || eq == 0) {
        throw UsageError("--set '" + value +
                         "': expected key.sub=value, e.g. --set outline.width=3");
      }
      o.sets.emplace_back(value.substr(0, eq), value.substr(eq + 1));
      seen_flags.push_back("--set");
    } else if (c.take("-o", value) || c.take("--output", value)) {
      if (value.empty()) throw UsageError("-o needs a file name (or - for standard output)");
      set_once(output, value, "-o");
      seen_flags.push_back("-o");
    } else if (c.take("--models", value)) {
      if (value.empty()) throw UsageError("--models needs a folder");
      set_once(models_dir, value, "--models");
      seen_flags.push_back("--models");
    } else if (c.take("--size", value)) {
      set_once(size, value, "--size");
      seen_flags.push_back("--size");
    } else if (a == "--all") {
      o.all_models = true;
      seen_flags.push_back("--all");
    } else if (c.take("--only", value)) {
      for (std::string& name : split_names(value)) o.only.push_back(std::move(name));
      seen_flags.push_back("--only");
    } else {
      throw UsageError("unknown option '" + a + "' (see toon --help)");
    }
  }

  if (model) o.model_id = *model;
  if (params) o.params_file = *params;
  if (output) o.output = *output;
  if (models_dir) o.models_dir = *models_dir;
  if (size) o.size = parse_size(*size);

  // Help and version answer without a server, so a bad URL must not stop them.
  if (o.help || o.version) return o;

  if (server) {
    o.server = *server;
  } else if (env_server && !env_server->empty()) {
    o.server = *env_server;
  } else {
    o.server = std::string(kDefaultServer);
  }
  parse_server_url(o.server);
  while (o.server.size() > 1 && o.server.back() == '/') o.server.pop_back();

  if (o.verb == Verb::none) {
    throw UsageError("no command given (health, upload, render or gallery)");
  }

  const std::string verb(verb_name(o.verb));
  for (const std::string& flag : seen_flags) {
    if (!flag_allowed(flag, o.verb))
      throw UsageError(verb + " does not take " + flag + " (see toon " + verb + " --help)");
  }

  switch (o.verb) {
    case Verb::health:
      if (!positionals.empty()) {
        throw UsageError("health takes no arguments, got '" + positionals.front() + "'");
      }
      break;
    case Verb::upload:
      if (positionals.empty()) throw UsageError("upload needs the path of an .obj (or .m) file");
      if (positionals.size() > 1) {
        throw UsageError("upload takes one model file, got '" + positionals[1] + "' too");
      }
      o.obj_path = positionals.front();
      break;
    case Verb::render:
      if (positionals.size() > 1) {
        throw UsageError("render takes at most one model file, got '" + positionals[1] + "' too");
      }
      if (!positionals.empty()) o.obj_path = positionals.front();
      if (!o.obj_path.empty() && !o.model_id.empty()) {
        throw UsageError("give either a model file or --model ID, not both");
      }
      if (o.output.empty()) {
        throw UsageError("render needs -o OUT.png (or -o - for standard output)");
      }
      break;
    case Verb::gallery:
      if (!positionals.empty()) {
        throw UsageError("gallery takes no arguments, got '" + positionals.front() +
                         "' (the models come from --models DIR)");
      }
      if (o.output.empty()) throw UsageError("gallery needs -o OUTDIR, the folder to write");
      if (o.output == "-") throw UsageError("gallery writes a folder; -o - is not possible");
      if (o.all_models && !o.only.empty()) throw UsageError("give either --all or --only, not both");
      break;
    case Verb::none: break;
  }
  return o;
}

nlohmann::json build_render_params(const Options& options, const proto::ParamSchema& schema) {
  json params = json::object();
  if (!options.params_file.empty()) {
    const std::string where = options.params_file == "-" ? "standard input" : options.params_file;
    try {
      params = json::parse(read_params_text(options.params_file));
    } catch (const json::parse_error& e) {
      throw UsageError("--params " + where + ": not valid JSON: " + plain_json_error(e.what()));
    }
    if (!params.is_object()) {
      throw UsageError("--params " + where + ": render parameters must be a JSON object");
    }
  }

  for (const auto& [key, text] : options.sets) {
    try {
      schema.set_from_text(params, key, text);
    } catch (const RequestError& e) {
      // The schema's message may already start with "key=value: ".
      const std::string message = e.what();
      const std::string assignment = key + "=" + text;
      throw UsageError("--set " +
                       (message.rfind(assignment, 0) == 0 ? message : assignment + ": " + message));
    } catch (const json::exception& e) {
      // A --set that walks into a scalar the params file already holds
      // ("--set outline.width.x=1" after "outline": 3).
      throw UsageError("--set " + key + "=" + text + ": " + plain_json_error(e.what()));
    }
  }

  if (!options.model_id.empty()) params["model"] = options.model_id;
  if (!options.obj_path.empty() && params.contains("model")) {
    throw UsageError("the parameters name model " + params["model"].dump() + " but " +
                     options.obj_path + " is uploaded with the request; drop one");
  }

  try {
    schema.validate(params);
  } catch (const RequestError& e) {
    std::string message = "invalid render parameters: ";
    message += e.what();
    if (e.code() == "unknown_parameter" && !e.path().empty()) message += " at " + e.path();
    throw UsageError(message);
  }
  return params;
}

std::string usage_text(Verb verb) {
  switch (verb) {
    case Verb::health:
      return R"(Usage: toon [--server URL] health

Asks the daemon for GET /healthz and prints its answer: status and the
OpenGL vendor, renderer and version it renders with.
Exit status 0 when the status is "ok", 1 otherwise or when it cannot be reached.
)";
    case Verb::upload:
      return R"(Usage: toon [--server URL] upload PATH.obj|PATH.m|PATH.glb|PATH.gltf|FOLDER [-q]

Sends an OBJ model to the daemon's store (POST /models) together with the
MTL files its mtllib lines name and the textures those MTL files reference
(map_Kd, map_Ks, map_Ns, map_d, map_Bump, bump, norm, disp). Files are sent
with their path relative to the OBJ's folder; references that leave that
folder are refused, missing files are reported and skipped. A .m mesh
(`Vertex i x y z {normal=(...)}` / `Face i a b c` lines) and a .glb are
sent alone; a .gltf brings the .bin and image files its URIs name (inside its
folder). A folder stands for its one model file (.obj, .m, .gltf or .glb).
Prints the daemon's answer (id, triangles, materials, textures, warnings).

Options:
  -q, --quiet   print only the model id
)";
    case Verb::render:
      return R"(Usage: toon [--server URL] render [PATH.obj|PATH.m | --model ID] [--params FILE.json]
                           [--set key.sub=value ...] -o OUT.png

Renders a PNG (POST /render). With PATH.obj (or a .m, .gltf or .glb model) the model and
its MTL files and textures are uploaded with the request; with --model a stored model is used;
with neither the daemon's built-in demo model renders.

Options:
  --model ID          render a model stored earlier with `toon upload`
  --params FILE.json  start from this JSON of render parameters (- reads stdin)
  --set key.sub=value set one parameter, checked against the schema before
                      anything is sent; may be repeated, later ones win.
                      Arrays and objects are written as JSON:
                        --set outline.width=3 --set shading.steps=4
                        --set background=[1,1,1] --set lights.0.intensity=1.5
  -o, --output FILE   where to write the PNG (required; - for standard output)
)";
    case Verb::gallery:
      return R"(Usage: toon [--server URL] gallery [--models DIR] [--all | --only NAME[,NAME...]]
                            [--size N] -o OUTDIR

Renders every preset the daemon offers (GET /presets) and one look per
effect (specular, rim, halftone, contours, shadows, two-tone, a colour ramp,
outline colours, antialiasing, coloured and point lights) on each model, and
writes OUTDIR/<model>/<look>.png, OUTDIR/contact-sheet.png (rows are models,
columns are looks) and OUTDIR/index.html, which shows every image with its
exact parameters and the `toon render` command that repeats it.
A model is a folder of DIR with exactly one .obj directly inside; its MTL
files and textures are found as `toon upload` finds them. NAME.glb stands
for folder NAME's model sent as a .glb that toon writes from its OBJ (kept
as OUTDIR/NAME.glb/<obj name>.glb), so glTF is shown too. Progress goes to
stderr. A failed render is reported and the rest still run and are written;
the exit status is then 1.

Options:
  --models DIR        the folder of model folders (default: ../shared/models)
  --all               every model folder in DIR, then bob.glb (default:
                      spot, kenney-cube-pet-dog, kenney-space-craft,
                      windmill, stanford-bunny, utah-teapot, bob.glb)
  --only NAME[,NAME]  just these model folders, in this order; may be repeated
  --size N            width and height of each render in pixels (default 256)
  -o, --output DIR    the folder to write (created if missing; required)
)";
    case Verb::none: break;
  }
  return R"(toon - command-line client for toond, the toon-rendering daemon

Usage:
  toon [--server URL] health
  toon [--server URL] upload PATH.obj|PATH.m|PATH.glb|PATH.gltf|FOLDER [-q]
  toon [--server URL] render [PATH.obj|PATH.m | --model ID] [--params FILE.json]
                             [--set key.sub=value ...] -o OUT.png
  toon [--server URL] gallery [--models DIR] [--all | --only NAME,...] [--size N]
                              -o OUTDIR

Commands:
  health    show the daemon's status and the OpenGL renderer it uses
  upload    store an OBJ with its MTL files and textures (or a .m mesh);
            prints the model id
  render    render a PNG of a local OBJ, a stored model or the demo model
  gallery   render every preset and effect on a folder of models into PNGs,
            a contact sheet and an HTML index
  help CMD  show the options of one command (same as toon CMD --help)

Global options (before or after the command):
  --server URL   toond's address (default: $TOOND_URL, else http://127.0.0.1:8080)
  -h, --help     show this help
  --version      print toon's version

Exit status: 0 success, 1 server or network error, 2 usage or parameter error.
)";
}

}  // namespace toond::cli
