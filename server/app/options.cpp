#include "app/options.h"

#include <cstdlib>
#include <span>
#include <stdexcept>

#include "app/flag_values.h"
#include "app/limit_options.h"

namespace toond::app {
namespace {

// Megabytes given, bytes kept.
std::size_t megabytes(const std::string& flag, const std::string& text, unsigned long long min) {
  return static_cast<std::size_t>(parse_count(flag, text, min, 1 << 20)) << 20;
}

constexpr const char* kMaxStoreVariable = "TOOND_MAX_STORE_MB";

// A store's bound: megabytes (MiB) up to a pebibyte, bytes kept.
std::uint64_t store_megabytes(const std::string& flag, const std::string& text) {
  return std::uint64_t{parse_count(flag, text, 0, 1ull << 30)} << 20;
}

using Value = const std::string&;

const Flag kGeneralFlags[] = {
    {{"", "--listen", "HOST:PORT",
      "address to serve on (default 127.0.0.1:8080; port 0 picks\n"
      "a free port). Prints \"listening on http://HOST:PORT\" when ready."},
     [](Options& o, Value, Value v) {
       const auto colon = v.rfind(':');
       if (colon == std::string::npos || colon == 0) {
         throw std::invalid_argument("--listen expects HOST:PORT, got '" + v + "'");
       }
       o.host = v.substr(0, colon);
       o.port = static_cast<int>(parse_count("--listen port", v.substr(colon + 1), 0, 65535));
     }},
    {{"", "--data-dir", "DIR", "where uploaded models are stored (default ./toond-data)"},
     [](Options& o, Value, Value v) { o.data_dir = v; }},
    {{"", "--max-store-mb", "N",
      "bound the stored models (their files) to N MiB: past it\n"
      "the least recently used (last upload or render) are let\n"
      "go, never one a queued or running render holds, on every\n"
      "replica sharing the data directory; a let-go id answers\n"
      "404 unknown_model. Default: the TOOND_MAX_STORE_MB\n"
      "environment variable, else 0 (no bound)"},
     [](Options& o, Value flag, Value v) { o.max_store_bytes = store_megabytes(flag, v); }},
    {{"", "--gpu", "N",
      "use EGL device N (see --list-gpus); default: the first\n"
      "hardware device, else Mesa's surfaceless platform"},
     [](Options& o, Value flag, Value v) { o.gpu = static_cast<int>(parse_count(flag, v, 0, 1024)); }},
    {{"", "--list-gpus", "", "print the EGL devices and exit"}, [](Options& o, Value, Value) { o.list_gpus = true; }},
    {{"", "--queue", "N", "render jobs allowed to wait in each lane (default 32); beyond: 503"},
     [](Options& o, Value flag, Value v) { o.queue = static_cast<std::size_t>(parse_count(flag, v, 1, 100000)); }},
    {{"", "--render-threads", "N",
      "render threads, each with its own GL context and its\n"
      "own GPU copies of the models (default 1)"},
     [](Options& o, Value flag, Value v) { o.render_threads = static_cast<std::size_t>(parse_count(flag, v, 1, 64)); }},
    {{"", "--frames-in-flight", "N",
      "1 (default): each frame is read back before the next one\n"
      "is drawn; 2: a render thread records the next queued frame\n"
      "while the last one's pixels come back (a pixel buffer and\n"
      "a fence), so a GPU draws while it packs; the same bytes"},
     [](Options& o, Value flag, Value v) { o.frames_in_flight = static_cast<int>(parse_count(flag, v, 1, 2)); }},
    {{"", "--long-render-cost", "M",
      "renders predicted to cost M Msamples or more (see\n"
      "--max-render-cost) wait in a lane of their own, served\n"
      "by one more render thread and context, so they never\n"
      "hold up shorter ones (default 300; 0: one lane)"},
     [](Options& o, Value flag, Value v) {
       o.long_render_cost = static_cast<double>(parse_count(flag, v, 0, 1ull << 40));
     }},
    {{"", "--max-upload-bytes", "N", "largest request body accepted (default 268435456)"},
     [](Options& o, Value flag, Value v) {
       o.max_upload_bytes = static_cast<std::size_t>(parse_count(flag, v, 1024, 1ull << 40));
     }},
    {{"", "--threads", "N", "HTTP worker threads (default 8)"},
     [](Options& o, Value flag, Value v) { o.threads = static_cast<int>(parse_count(flag, v, 1, 1024)); }},
    {{"", "--result-cache-mb", "N",
      "memory for finished PNGs answering identical requests\n"
      "(same model and parameters) without rendering; least\n"
      "recently used out first (default 64; 0: off; always\n"
      "off with --shader-dir)"},
     [](Options& o, Value flag, Value v) { o.result_cache_bytes = megabytes(flag, v, 0); }},
    {{"", "--gpu-cache-mb", "N",
      "GPU memory for models kept uploaded between renders\n"
      "(default 1024; at most 8 models); least recently used\n"
      "out first"},
     [](Options& o, Value flag, Value v) { o.gpu_cache_bytes = megabytes(flag, v, 1); }},
    {{"", "--render-timeout", "S",
      "seconds a request waits for its render (default 10;\n"
      "fractions allowed). Past it: 503 \"deadline_exceeded\"\n"
      "with Retry-After, and a job not yet started is dropped;\n"
      "a long render (see --long-render-cost) is stopped\n"
      "between chunks of triangles: 503 \"render_aborted\""},
     [](Options& o, Value flag, Value v) { o.render_timeout_s = parse_seconds(flag, v, 0.001, 86400); }},
    {{"", "--shader-dir", "DIR",
      "read the GLSL files (the names in shaders/) from DIR\n"
      "instead of the embedded copies, and recompile before a\n"
      "render when one changed. A file missing in DIR is an\n"
      "error (no fallback to the embedded copy). A file that\n"
      "does not compile fails that render (500 \"shader_error\"\n"
      "naming the file and line); the previous shaders keep\n"
      "serving until the file is fixed."},
     [](Options& o, Value flag, Value v) { o.shader_dir = non_empty(flag, v, "a directory"); }},
    {{"", "--simulate-gpu-reset", "N",
      "testing aid: every Nth render acts as if the GL context\n"
      "had been lost (a GPU reset), to exercise the recovery\n"
      "a real loss takes: that request gets 503 \"gpu_reset\"\n"
      "with Retry-After, the render thread makes a new\n"
      "context and uploads models again as they are used.\n"
      "Real losses are detected on robust contexts (EGL 1.5\n"
      "or EGL_KHR_create_context / EGL_EXT_create_context_\n"
      "robustness), which toond asks for where it can."},
     [](Options& o, Value flag, Value v) {
       o.simulate_gpu_reset = static_cast<std::size_t>(parse_count(flag, v, 1, 1'000'000'000));
     }},
    {{"", "--skinning", "WHERE",
      "where a pose (a request's `animation`) moves the vertices:\n"
      "gpu (in the vertex stage of every pass, from the pose's\n"
      "joint matrices), cpu (once per render, over the cores,\n"
      "straight into the vertex buffer), or auto (default): gpu\n"
      "on a GPU, cpu on a software rasterizer such as llvmpipe,\n"
      "whose vertex stage runs on the CPU again for every pass"},
     [](Options& o, Value flag, Value v) {
       if (v == "gpu")
         o.skinning = Options::Skinning::Gpu;
       else if (v == "cpu")
         o.skinning = Options::Skinning::Cpu;
       else if (v == "auto")
         o.skinning = Options::Skinning::Auto;
       else
         throw std::invalid_argument(flag + " expects gpu, cpu or auto, got '" + v + "'");
     }},
    {{"", "--version", "", "print the version and exit"}, [](Options& o, Value, Value) { o.version = true; }},
    {{"-h", "--help", "", "this text"}, [](Options& o, Value, Value) { o.help = true; }},
};

// --help's sections in order: a heading (none for the first) and its flags.
struct Section {
  const char* heading;
  std::span<const Flag> flags;
};

std::vector<Section> sections() {
  return {{"", kGeneralFlags},
          {"Limits (over one: 413 for bytes, 422 for counts, {\"error\":{\"code\":\"limit_exceeded\",\n"
           "\"limit\":\"--max-...\",...}}):\n",
           limit_flags()},
          {"Access:\n", access_flags()}};
}

const Flag* find_flag(const std::string& arg) {
  for (const Section& section : sections()) {
    for (const Flag& flag : section.flags) {
      if (arg == flag.help.name || (!flag.help.alias.empty() && arg == flag.help.alias)) return &flag;
    }
  }
  return nullptr;
}

}  // namespace

void apply_store_environment(Options& options) {
  if (options.max_store_bytes) return;
  const char* value = std::getenv(kMaxStoreVariable);
  options.max_store_bytes = value != nullptr && *value != '\0' ? store_megabytes(kMaxStoreVariable, value) : 0;
}

std::vector<text::OptionHelp> flag_list() {
  std::vector<text::OptionHelp> flags;
  for (const Section& section : sections()) {
    for (const Flag& flag : section.flags) flags.push_back(flag.help);
  }
  return flags;
}

std::string usage() {
  const std::size_t column = text::help_column(flag_list(), 2);
  std::string text = "toond - headless toon-rendering service\n\nUsage: toond [options]\n\n";
  for (const Section& section : sections()) {
    text += section.heading;
    for (const Flag& flag : section.flags) text += text::option_lines(flag.help, 2, column);
  }
  return text + R"(
Routes: GET /healthz, GET/POST /models, GET/DELETE /models/{id}, POST /render,
GET /schema, GET / (web page). See proto/openapi.yaml.
)";
}

Options parse_options(const std::vector<std::string>& args) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const Flag* flag = find_flag(a);
    if (!flag) throw std::invalid_argument("unknown option '" + a + "' (see --help)");
    std::string value;
    if (!flag->help.value.empty()) {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      value = args[++i];
    }
    flag->apply(o, a, value);
  }
  return o;
}

}  // namespace toond::app
