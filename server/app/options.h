#pragma once
// toond's command line. Every flag has a default and is listed by --help.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "http/access_control.h"
#include "http/request_limits.h"
#include "text/option_help.h"

namespace toond::app {

struct Options {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port
  std::string data_dir = "toond-data";
  std::optional<int> gpu;
  std::size_t queue = 32;
  std::size_t render_threads = 1;  // each with its own GL context
  // Msamples (render/plan/render_cost.h) from which a render waits in the long
  // lane, served by a render thread of its own; 0: one lane.
  double long_render_cost = 300;
  std::size_t max_upload_bytes = 256u << 20;
  int threads = 8;
  // Finished PNGs kept for identical requests; 0 turns the cache off.
  std::size_t result_cache_bytes = std::size_t{64} << 20;
  // GPU memory for uploaded models kept between renders.
  std::size_t gpu_cache_bytes = std::size_t{1} << 30;
  double render_timeout_s = 10;
  // Empty: the shaders embedded in the binary. Otherwise GLSL files are read
  // from this folder and recompiled when they change (look development).
  std::string shader_dir;
  // Bytes of stored models kept at most (--max-store-mb, else the
  // TOOND_MAX_STORE_MB environment variable); 0: no bound. Unset until
  // apply_store_environment() has had its say.
  std::optional<std::uint64_t> max_store_bytes;
  // Testing aid: every Nth render acts as if the GL context were lost.
  std::size_t simulate_gpu_reset = 0;
  // RenderService::Options::frames_in_flight.
  int frames_in_flight = 1;
  // Where poses move vertices (RenderService::Options::skinning).
  enum class Skinning { Auto, Gpu, Cpu } skinning = Skinning::Auto;
  // --max-* (server/app/limit_options.cpp); max_upload_bytes above wins
  // over limits.max_upload_bytes.
  http::RequestLimits limits;
  http::AccessOptions access;  // --token / TOOND_TOKEN, --cors-origin
  bool list_gpus = false;
  bool help = false;
  bool version = false;
};

// Parses argv. Throws std::invalid_argument with a message naming the flag.
Options parse_options(const std::vector<std::string>& args);
// --max-store-mb when given, else TOOND_MAX_STORE_MB, else 0. Throws
// std::invalid_argument naming the variable for a bad value.
void apply_store_environment(Options& options);
// --help: every flag of flag_list() with its help, by section.
std::string usage();
// Every flag parse_options() reads, in --help's order.
std::vector<text::OptionHelp> flag_list();

}  // namespace toond::app
