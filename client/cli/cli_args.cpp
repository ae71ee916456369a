#include "cli_args.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_flags.h"
#include "param_schema.h"
#include "request_error.h"

namespace toond::cli {
namespace {

using nlohmann::json;

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
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

// "health, upload, render, gallery", the last joined by `last`.
std::string verb_names(std::string_view last) {
  std::string names;
  const auto all = verbs();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (i > 0) names += i + 1 == all.size() ? last : ", ";
    names += all[i].name;
  }
  return names;
}

Verb verb_from_name(std::string_view name) {
  for (const VerbInfo& v : verbs()) {
    if (v.name == name) return v.verb;
  }
  throw UsageError("unknown command '" + std::string(name) + "' (commands: " + verb_names(", ") + "; see toon --help)");
}

// The row that the current argument names, its value read into `value`:
// `--name value` or `--name=value` for a flag that takes one, the bare name
// for a switch. Null when it names none.
const Flag* take_flag(ArgCursor& c, std::string& value) {
  for (const Flag& flag : flags()) {
    for (const std::string_view name : {flag.help.alias, flag.help.name}) {
      if (name.empty()) continue;
      if (flag.help.value.empty() ? c.current() == name : c.take(name, value)) return &flag;
    }
  }
  return nullptr;
}

// Whether any row of the flag called `name` belongs to `verb`.
bool flag_allowed(std::string_view name, Verb verb) {
  return std::any_of(flags().begin(), flags().end(),
                     [&](const Flag& flag) { return flag.help.name == name && (flag.verbs & verb_set(verb)) != 0; });
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

}  // namespace

std::string_view verb_name(Verb verb) {
  for (const VerbInfo& v : verbs()) {
    if (v.verb == verb) return v.name;
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

namespace {

// The command line's words sorted: the verb and flags go into the options
// (flags through their rows), the rest are the verb's arguments.
struct ReadLine {
  std::vector<std::string> positionals;
  std::vector<const Flag*> seen;  // to check against the verb once it is known
  std::optional<std::string> server;
  bool verb_seen = false;
  bool help_verb = false;  // `toon help render`
};

// A word that is not a flag: the verb (or `help VERB`'s), else an argument.
void take_word(const std::string& word, Options& o, ReadLine& line) {
  if (!line.verb_seen) {
    line.verb_seen = true;
    if (word == "help") {
      line.help_verb = true;
      o.help = true;
    } else {
      o.verb = verb_from_name(word);
    }
  } else if (line.help_verb && o.verb == Verb::none) {
    o.verb = verb_from_name(word);
  } else {
    line.positionals.push_back(word);
  }
}

ReadLine read_line(const std::vector<std::string>& args, Options& o) {
  ReadLine line;
  FlagTarget target{o, std::nullopt};
  bool options_ended = false;
  for (ArgCursor c(args); !c.done(); c.next()) {
    const std::string& a = c.current();
    const bool looks_like_flag = !options_ended && a.size() > 1 && a[0] == '-';
    if (!looks_like_flag) {
      take_word(a, o, line);
      continue;
    }
    if (a == "--") {
      options_ended = true;
      continue;
    }
    std::string value;
    const Flag* flag = take_flag(c, value);
    if (!flag) throw UsageError("unknown option '" + a + "' (see toon --help)");
    const bool again =
        std::any_of(line.seen.begin(), line.seen.end(), [&](const Flag* f) { return f->help.name == flag->help.name; });
    if (again && !flag->repeatable) throw UsageError(flag_display(flag->help) + " given twice");
    flag->apply(target, value);
    line.seen.push_back(flag);
  }
  line.server = target.server;
  return line;
}

// --server, else TOOND_URL, else the default; checked, trailing '/' dropped.
std::string server_of(const std::optional<std::string>& flag, const std::optional<std::string>& env_server) {
  std::string server = flag ? *flag : env_server && !env_server->empty() ? *env_server : std::string(kDefaultServer);
  parse_server_url(server);
  while (server.size() > 1 && server.back() == '/') server.pop_back();
  return server;
}

void check_flags_fit(const std::vector<const Flag*>& seen, Verb verb) {
  const std::string name(verb_name(verb));
  for (const Flag* flag : seen) {
    if (!flag_allowed(flag->help.name, verb)) {
      throw UsageError(name + " does not take " + flag_display(flag->help) + " (see toon " + name + " --help)");
    }
  }
}

// The verb's arguments into the options, and what the verb cannot do without.
void take_positionals(Options& o, const std::vector<std::string>& positionals) {
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
    case Verb::info:
      if (positionals.size() != 1) throw UsageError("info needs one model id (toon info ID)");
      o.model_id = positionals.front();
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
    case Verb::none:
      break;
  }
}

}  // namespace

Options parse_args(const std::vector<std::string>& args, const std::optional<std::string>& env_server) {
  Options o;
  const ReadLine line = read_line(args, o);
  // Help and version answer without a server, so a bad URL must not stop them.
  if (o.help || o.version) return o;
  o.server = server_of(line.server, env_server);
  if (o.verb == Verb::none) throw UsageError("no command given (" + verb_names(" or ") + ")");
  check_flags_fit(line.seen, o.verb);
  take_positionals(o, line.positionals);
  return o;
}

namespace {

// -o NAME.svg asks for the lines as vectors (output svg); parameters that
// name another output contradict it.
void apply_output_extension(const std::string& file, json& params) {
  std::string lower = file;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (!lower.ends_with(".svg")) return;
  if (params.contains("output") && params["output"] != "svg") {
    throw UsageError("-o " + file + ": an .svg file holds output svg, but the parameters ask for output " +
                     params["output"].dump() + "; drop one");
  }
  params["output"] = "svg";
}

}  // namespace

nlohmann::json build_render_params(const Options& options, const proto::ParamSchema& schema,
                                   const ClipsOfModel& clips_of) {
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

  const auto set = [&](const std::string& key, const std::string& text, const std::string& value) {
    try {
      schema.set_from_text(params, key, value);
    } catch (const RequestError& e) {
      // The schema's message may already start with "key=value: ".
      const std::string message = e.what();
      const std::string assignment = key + "=" + value;
      throw UsageError("--set " + key + "=" + text + ": " +
                       (message.rfind(assignment, 0) == 0 ? message.substr(assignment.size() + 2) : message));
    } catch (const json::exception& e) {
      // A --set that walks into a scalar the params file already holds
      // ("--set outline.width.x=1" after "outline": 3).
      throw UsageError("--set " + key + "=" + text + ": " + plain_json_error(e.what()));
    }
  };
  // Ranges in frames wait for the clip and the model they need.
  std::vector<std::pair<std::string, std::string>> in_frames;
  for (const auto& [key, text] : options.sets) {
    if (frame_range_of(key, text)) {
      in_frames.emplace_back(key, text);
    } else {
      set(key, text, text);
    }
  }

  if (!options.model_id.empty()) params["model"] = options.model_id;
  for (const auto& [key, text] : in_frames) {
    set(key, text, range_in_seconds(params, key, text, *frame_range_of(key, text), clips_of));
  }
  apply_output_extension(options.output, params);
  if (!options.obj_path.empty() && params.contains("model")) {
    throw UsageError("the parameters name model " + params["model"].dump() + " but " + options.obj_path +
                     " is uploaded with the request; drop one");
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

}  // namespace toond::cli
