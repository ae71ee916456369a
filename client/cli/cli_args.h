#pragma once
// Command-line parsing for `toon`, kept apart from the network code so every
// rule (where --server may stand, which flags a verb takes, how --set is
// checked) can be unit-tested without a daemon.
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frame_ranges.h"

namespace toond::proto {
class ParamSchema;
}

namespace toond::cli {

inline constexpr std::string_view kDefaultServer = "http://127.0.0.1:8080";
// `toon gallery` defaults: the shared models beside a checkout, 256² renders.
inline constexpr std::string_view kDefaultModelsDir = "../shared/models";
inline constexpr int kDefaultGallerySize = 256;

// Everything the user got wrong before a request is made: exit status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Verb { none, health, upload, info, render, gallery };

struct Options {
  Verb verb = Verb::none;
  std::string server;  // already resolved: --server, else TOOND_URL, else the default
  bool help = false;
  bool version = false;

  // upload and render
  std::string obj_path;
  // upload
  bool quiet = false;
  std::string scene;         // a glTF scene's index (POST /models?scene=N); empty: the file's default
  std::string smooth_angle;  // POST /models?smooth_angle=D; empty: the daemon's default (30)
  std::string up;            // POST /models?up=y|z; empty: y
  std::string textures;      // POST /models?textures=LIST: images on the materials; empty: none
  // render, info
  std::string model_id;
  std::string params_file;                                // "-" reads standard input
  std::vector<std::pair<std::string, std::string>> sets;  // in command-line order
  std::string output;                                     // "-" writes to standard output;
                                                          // gallery: the output folder
  // gallery
  std::string models_dir = std::string(kDefaultModelsDir);
  int size = kDefaultGallerySize;
  bool all_models = false;
  std::vector<std::string> only;  // --only NAME[,NAME]: these model folders, in this order
};

// `args` excludes argv[0]. `env_server` is TOOND_URL (nullopt when unset), a
// parameter so tests need not touch the process environment. Throws
// UsageError. With help or version set, the verb's own requirements (a
// path, -o) are not enforced.
Options parse_args(const std::vector<std::string>& args, const std::optional<std::string>& env_server);

// TOOND_URL from the environment; an empty value counts as unset.
std::optional<std::string> server_from_environment();

// The render request the options describe: the --params file, then each
// --set in order, then --model, then each clip range given in frames
// (168f,187f: frame_ranges.h), turned into seconds with the frame rates
// `clips_of` reads from the daemon; validated against the schema. Throws
// UsageError naming the file or key at fault.
nlohmann::json build_render_params(const Options& options, const proto::ParamSchema& schema,
                                   const ClipsOfModel& clips_of = {});

// Usage text for one verb, or the overview for Verb::none.
std::string usage_text(Verb verb);

std::string_view verb_name(Verb verb);

// A --server URL split the way httplib wants it: "http://host:port" for the
// client plus the path prefix a reverse proxy may put in front of toond.
struct ServerUrl {
  std::string scheme_host_port;
  std::string base_path;  // "" or "/prefix" without a trailing slash
};
// Throws UsageError for anything but http:// or https:// with a host.
ServerUrl parse_server_url(std::string_view url);

}  // namespace toond::cli
