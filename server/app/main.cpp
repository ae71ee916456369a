// toond: starts the render thread (EGL context), opens the model store and
// serves the HTTP API until SIGINT/SIGTERM, then finishes accepted work.
#include <csignal>
#include <filesystem>
#include <iostream>

#include <httplib.h>

#include "app/options.h"
#include "gpu/egl_context.h"
#include "http/routes.h"
#include "render/model_library.h"
#include "render/render_service.h"
#include "scene/model_store.h"

namespace {

httplib::Server* g_server = nullptr;

void on_signal(int) {
  // httplib's stop() only flips flags and shuts the listening socket down,
  // which is safe enough here: the main thread returns from listen().
  if (g_server) g_server->stop();
}

int run(const toond::app::Options& options) {
  if (options.list_gpus) {
    const auto devices = toond::gpu::EglContext::enumerate_devices();
    if (devices.empty()) std::cout << "no EGL devices enumerated (Mesa surfaceless will be used)\n";
    for (const auto& d : devices) {
      std::cout << d.index << ": " << (d.software ? "software" : "hardware")
                << (d.drm_file.empty() ? "" : " " + d.drm_file) << "\n";
    }
    return 0;
  }

  toond::scene::ModelStore store(options.data_dir);
  toond::render::RenderService::Options render_options;
  render_options.gpu_index = options.gpu;
  render_options.queue_capacity = options.queue;
  render_options.shader_dir = options.shader_dir;
  toond::render::RenderService renderer(render_options);
  toond::render::ModelLibrary library(store, 16);

  httplib::Server server;
  server.new_task_queue = [n = options.threads] { return new httplib::ThreadPool(static_cast<std::size_t>(n)); };
  server.set_payload_max_length(options.max_upload_bytes);
  toond::http::ServiceContext context{store, library, renderer,
                                      std::chrono::milliseconds(static_cast<long long>(options.render_timeout_s * 1000))};
  // Edited shaders change the image of the same parameters: no cache then.
  if (options.result_cache_bytes > 0 && options.shader_dir.empty()) {
    context.results = std::make_unique<toond::render::ResultCache>(options.result_cache_bytes);
  }
  toond::http::register_routes(server, context);

  const int port = options.port == 0 ? server.bind_to_any_port(options.host)
                                     : (server.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    std::cerr << "toond: cannot listen on " << options.host << ":" << options.port << "\n";
    return 1;
  }
  std::cerr << "toond: GL " << renderer.gl_info().version << " on " << renderer.gl_info().renderer
            << " (" << renderer.gl_info().platform << "), data in " << options.data_dir
            << (options.shader_dir.empty() ? "" : ", shaders from " + options.shader_dir + " (reloaded on change)")
            << "\n";
  std::cout << "listening on http://" << options.host << ":" << port << std::endl;

  g_server = &server;
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  const bool ok = server.listen_after_bind();
  g_server = nullptr;
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  toond::app::Options options;
  try {
    options = toond::app::parse_options(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::invalid_argument& e) {
    std::cerr << "toond: " << e.what() << "\n";
    return 2;
  }
  if (options.help) {
    std::cout << toond::app::usage();
    return 0;
  }
  if (options.version) {
    std::cout << "toond " << TOOND_VERSION << "\n";
    return 0;
  }
  if (!options.shader_dir.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_directory(options.shader_dir, ec)) {
      std::cerr << "toond: --shader-dir " << options.shader_dir << ": "
                << (std::filesystem::exists(options.shader_dir, ec) ? "not a directory" : "no such directory")
                << "\n";
      return 2;
    }
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "toond: " << e.what() << "\n";
    return 1;
  }
}
