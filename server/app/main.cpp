// toond: starts the render thread (EGL context), opens the model store and
// serves the HTTP API until SIGINT/SIGTERM, then finishes accepted work.
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <thread>

#include <httplib.h>

#include "app/limit_options.h"
#include "app/options.h"
#include "gpu/egl_context.h"
#include "http/access_control.h"
#include "http/listen_backlog.h"
#include "http/routes.h"
#include "pipeline/render_entry.h"
#include "render/run/render_service.h"
#include "scene/store/model_library.h"
#include "scene/store/model_store.h"

namespace {

// Connections the kernel may hold for the accept thread: every client of a
// busy replica reconnecting at once, with room to spare.
constexpr int kListenBacklog = 512;

// SIGINT/SIGTERM are blocked in every thread and taken by one thread with
// sigwait, so stopping the server runs as ordinary code, not in a signal
// handler. stop() ends listen(); httplib then lets every accepted request
// finish, and the render thread finishes the jobs already queued before it
// stops: a render in flight completes and the exit status is 0.
sigset_t termination_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

class SignalStopper {
 public:
  explicit SignalStopper(httplib::Server& server)
      : thread_([this, &server] {
          const sigset_t set = termination_signals();
          int signal = 0;
          sigwait(&set, &signal);
          if (done_) return;
          std::cerr << "toond: " << (signal == SIGINT ? "SIGINT" : "SIGTERM") << ", finishing the requests in flight\n";
          // A signal that comes before listen() has started must still stop it.
          while (!done_ && !server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
          server.stop();
        }) {}
  ~SignalStopper() {
    done_ = true;
    // Wakes the waiting thread when the server stopped for another reason.
    ::kill(::getpid(), SIGTERM);
    thread_.join();
  }
  SignalStopper(const SignalStopper&) = delete;
  SignalStopper& operator=(const SignalStopper&) = delete;

 private:
  std::atomic<bool> done_{false};
  std::thread thread_;
};

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

  // Before any thread starts, so every thread inherits the mask.
  const sigset_t signals = termination_signals();
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);  // a client that hangs up is a failed write, not a crash

  toond::scene::StoreOptions store_options;
  store_options.max_bytes = options.max_store_bytes.value_or(0);
  // A lease outlives the longest a request holds a model: its wait for the
  // render, with room for the import and posing before it.
  store_options.lease_expiry =
      std::max(std::chrono::seconds(600), std::chrono::seconds(static_cast<long long>(2 * options.render_timeout_s)));
  toond::scene::ModelStore store(options.data_dir, store_options);
  toond::render::RenderService::Options render_options;
  render_options.gpu_index = options.gpu;
  render_options.queue_capacity = options.queue;
  render_options.render_threads = options.render_threads;
  render_options.frames_in_flight = options.frames_in_flight;
  render_options.long_render_cost = options.long_render_cost;
  render_options.shader_dir = options.shader_dir;
  render_options.gpu_model_bytes = options.gpu_cache_bytes;
  render_options.simulate_reset_every = options.simulate_gpu_reset;
  using Skinning = toond::app::Options::Skinning;
  if (options.skinning == Skinning::Gpu) render_options.skinning = toond::scene::Skinning::VertexStage;
  if (options.skinning == Skinning::Cpu) render_options.skinning = toond::scene::Skinning::Cpu;
  toond::render::RenderService renderer(render_options);
  toond::scene::ModelLibrary library(store, 16);
  toond::pipeline::RenderEntry::Settings entry_settings;
  entry_settings.limits = options.limits.render;
  entry_settings.deadline = std::chrono::milliseconds(static_cast<long long>(options.render_timeout_s * 1000));
  // Edited shaders change the image of the same parameters: no cache then.
  if (options.shader_dir.empty()) entry_settings.result_cache_bytes = options.result_cache_bytes;
  toond::pipeline::RenderEntry renders(store, library, renderer, entry_settings);

  httplib::Server server;
  server.new_task_queue = [n = options.threads] { return new httplib::ThreadPool(static_cast<std::size_t>(n)); };
  server.set_payload_max_length(options.max_upload_bytes);
  // An answer leaves in several writes (headers, then the PNG); with Nagle's
  // algorithm the last one waits for the client's delayed ACK of the first,
  // on every request of a kept-alive connection (a browser's); the test
  // ResultCache.KeptAliveConnectionsGetAnswersWithoutWaitingForAcks times it.
  server.set_tcp_nodelay(true);
  toond::http::ServiceContext context{store, renders};
  context.limits = options.limits;
  context.limits.max_upload_bytes = options.max_upload_bytes;
  toond::http::register_routes(server, context);
  toond::http::install_access_control(server, options.access);

  const int port = options.port == 0 ? server.bind_to_any_port(options.host)
                                     : (server.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    std::cerr << "toond: cannot listen on " << options.host << ":" << options.port << "\n";
    return 1;
  }
  if (toond::http::widen_listen_backlog(port, kListenBacklog) == 0) {
    std::cerr << "toond: could not widen the listen queue; clients reconnecting together may wait\n";
  }
  std::cerr << "toond: GL " << renderer.gl_info().version << " on " << renderer.gl_info().renderer << " ("
            << renderer.gl_info().platform
            << (renderer.gl_info().robust ? ", robust context" : ", no reset notification") << "), data in "
            << options.data_dir
            << (store_options.max_bytes
                    ? ", at most " + std::to_string(store_options.max_bytes >> 20) + " MiB of models"
                    : "")
            << (options.shader_dir.empty() ? "" : ", shaders from " + options.shader_dir + " (reloaded on change)")
            << "\n";
  std::cout << "listening on http://" << options.host << ":" << port << std::endl;

  SignalStopper stopper(server);
  const bool ok = server.listen_after_bind();
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  toond::app::Options options;
  try {
    options = toond::app::parse_options(std::vector<std::string>(argv + 1, argv + argc));
    toond::app::apply_access_environment(options.access);
    toond::app::apply_store_environment(options);
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
                << (std::filesystem::exists(options.shader_dir, ec) ? "not a directory" : "no such directory") << "\n";
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
