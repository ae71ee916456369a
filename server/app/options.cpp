#include "app/options.h"

#include <cstdlib>
#include <stdexcept>

namespace toond::app {
namespace {

long long parse_int(const std::string& flag, const std::string& text, long long min, long long max) {
  std::size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || v < min || v > max) {
    throw std::invalid_argument(flag + " expects an integer in " + std::to_string(min) + ".." +
                                std::to_string(max) + ", got '" + text + "'");
  }
  return v;
}

}  // namespace

std::string usage() {
  return R"(toond - headless toon-rendering service

Usage: toond [options]

  --listen HOST:PORT     address to serve on (default 127.0.0.1:8080; port 0 picks
                         a free port). Prints "listening on http://HOST:PORT" when ready.
  --data-dir DIR         where uploaded models are stored (default ./toond-data)
  --gpu N                use EGL device N (see --list-gpus); default: the first
                         hardware device, else Mesa's surfaceless platform
  --list-gpus            print the EGL devices and exit
  --queue N              render jobs allowed to wait (default 32); beyond: 503
  --render-threads N     render threads, each with its own GL context and its
                         own GPU copies of the models (default 1)
  --max-upload-bytes N   largest request body accepted (default 268435456)
  --threads N            HTTP worker threads (default 8)
  --result-cache-mb N    memory for finished PNGs answering identical requests
                         (same model and parameters) without rendering; least
                         recently used out first (default 64; 0: off; always
                         off with --shader-dir)
  --gpu-cache-mb N       GPU memory for models kept uploaded between renders
                         (default 1024; at most 8 models); least recently used
                         out first
  --render-timeout S     seconds a request waits for its render (default 60;
                         fractions allowed). Past it: 503 "deadline_exceeded"
                         with Retry-After, and a job not yet started is dropped
  --shader-dir DIR       read the GLSL files (the names in shaders/) from DIR
                         instead of the embedded copies, and recompile before a
                         render when one changed. A file missing in DIR is an
                         error (no fallback to the embedded copy). A file that
                         does not compile fails that render (500 "shader_error"
                         naming the file and line); the previous shaders keep
                         serving until the file is fixed.
  --simulate-gpu-reset N testing aid: every Nth render acts as if the GL context
                         had been lost (a GPU reset), to exercise the recovery
                         a real loss takes: that request gets 503 "gpu_reset"
                         with Retry-After, the render thread makes a new
                         context and uploads models again as they are used.
                         Real losses are detected on robust contexts (EGL 1.5
                         or EGL_KHR_create_context / EGL_EXT_create_context_
                         robustness), which toond asks for where it can.
  --version              print the version and exit
  -h, --help             this text
)" + limit_usage() + R"(
Routes: GET /healthz, GET/POST /models, GET/DELETE /models/{id}, POST /render,
GET /schema, GET / (web page). See proto/openapi.yaml.
)";
}

Options parse_options(const std::vector<std::string>& args) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--version") {
      o.version = true;
    } else if (a == "--list-gpus") {
      o.list_gpus = true;
    } else if (a == "--listen") {
      const std::string& v = value();
      const auto colon = v.rfind(':');
      if (colon == std::string::npos || colon == 0) {
        throw std::invalid_argument("--listen expects HOST:PORT, got '" + v + "'");
      }
      o.host = v.substr(0, colon);
      o.port = static_cast<int>(parse_int("--listen port", v.substr(colon + 1), 0, 65535));
    } else if (a == "--data-dir") {
      o.data_dir = value();
    } else if (a == "--gpu") {
      o.gpu = static_cast<int>(parse_int(a, value(), 0, 1024));
    } else if (a == "--queue") {
      o.queue = static_cast<std::size_t>(parse_int(a, value(), 1, 100000));
    } else if (a == "--render-threads") {
      o.render_threads = static_cast<std::size_t>(parse_int(a, value(), 1, 64));
    } else if (a == "--max-upload-bytes") {
      o.max_upload_bytes = static_cast<std::size_t>(parse_int(a, value(), 1024, 1LL << 40));
    } else if (a == "--gpu-cache-mb") {
      o.gpu_cache_bytes = static_cast<std::size_t>(parse_int(a, value(), 1, 1 << 20)) << 20;
    } else if (a == "--result-cache-mb") {
      o.result_cache_bytes = static_cast<std::size_t>(parse_int(a, value(), 0, 1 << 20)) << 20;
    } else if (a == "--threads") {
      o.threads = static_cast<int>(parse_int(a, value(), 1, 1024));
    } else if (a == "--shader-dir") {
      o.shader_dir = value();
      if (o.shader_dir.empty()) throw std::invalid_argument("--shader-dir needs a directory");
    } else if (a == "--simulate-gpu-reset") {
      o.simulate_gpu_reset = static_cast<std::size_t>(parse_int(a, value(), 1, 1'000'000'000));
    } else if (a == "--render-timeout") {
      const std::string& v = value();
      char* end = nullptr;
      const double seconds = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0' || !(seconds >= 0.001 && seconds <= 86400)) {
        throw std::invalid_argument("--render-timeout expects seconds in 0.001..86400, got '" + v + "'");
      }
      o.render_timeout_s = seconds;
    } else if (parse_limit_option(args, i, o.limits, o.access)) {
    } else {
      throw std::invalid_argument("unknown option '" + a + "' (see --help)");
    }
  }
  return o;
}

}  // namespace toond::app
