#include "support/nginx_balancer.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <httplib.h>

#include "support/daemon.h"

extern char** environ;

namespace toond::test {
namespace fs = std::filesystem;
namespace {

// A port nothing listens on right now. Another process may take it before
// nginx binds it; start() is retried with a new one when that happens.
int free_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) throw std::runtime_error("socket failed");
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = 0;
  socklen_t len = sizeof addr;
  const bool ok = ::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
                  ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0;
  ::close(fd);
  if (!ok) throw std::runtime_error("cannot find a free port");
  return ntohs(addr.sin_port);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string config(const fs::path& prefix, const std::vector<std::string>& upstreams, const fs::path& snippets,
                   int port) {
  const std::string p = prefix.string();
  std::ostringstream c;
  c << "daemon off;\n"
    << "master_process off;\n"
    << "worker_processes 1;\n"
    << "pid " << p << "/nginx.pid;\n"
    << "error_log " << p << "/error.log notice;\n"
    << "events { worker_connections 256; }\n"
    << "http {\n"
    << "  access_log " << p
    << "/access.log;\n"
    // Debian's build points these at /var/lib/nginx, which a test may not write.
    << "  client_body_temp_path " << p << "/body;\n"
    << "  proxy_temp_path " << p << "/proxy;\n"
    << "  fastcgi_temp_path " << p << "/fastcgi;\n"
    << "  uwsgi_temp_path " << p << "/uwsgi;\n"
    << "  scgi_temp_path " << p << "/scgi;\n"
    << "  include " << (snippets / "toond-model-hash.conf").string() << ";\n"
    << "  upstream toond {\n"
    // As docker/nginx/nginx.conf hashes (not `consistent`; it says why).
    << "    hash $toond_model_id;\n";
  for (const std::string& u : upstreams) c << "    server " << u << " max_fails=1 fail_timeout=30s;\n";
  c << "    keepalive 8;\n"
    << "  }\n"
    << "  server {\n"
    << "    listen 127.0.0.1:" << port << ";\n"
    << "    location / { include " << (snippets / "toond-proxy.conf").string() << "; }\n"
    << "  }\n"
    << "}\n";
  return c.str();
}

}  // namespace

std::string NginxBalancer::find_nginx() {
  std::vector<std::string> dirs;
  if (const char* path = std::getenv("PATH")) {
    std::istringstream s(path);
    for (std::string dir; std::getline(s, dir, ':');) dirs.push_back(dir);
  }
  dirs.push_back("/usr/sbin");
  for (const std::string& dir : dirs) {
    const fs::path candidate = fs::path(dir) / "nginx";
    if (!dir.empty() && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

NginxBalancer::NginxBalancer(const std::string& nginx, const std::vector<std::string>& upstreams,
                             const fs::path& snippet_dir)
    : prefix_(make_temp_dir("toond-nginx")) {
  for (int attempt = 0; attempt < 5; ++attempt) {
    const int port = free_port();
    std::ofstream(prefix_ / "nginx.conf") << config(prefix_, upstreams, snippet_dir, port);
    if (start(nginx, port)) return;
    if (error_log().find("Address already in use") == std::string::npos) break;
  }
  const std::string log = error_log() + read_text(prefix_ / "output.log");
  fs::remove_all(prefix_);
  throw std::runtime_error("nginx did not start:\n" + log);
}

bool NginxBalancer::start(const std::string& nginx, int port) {
  std::vector<std::string> args = {
      nginx, "-p", prefix_.string(), "-c", (prefix_ / "nginx.conf").string(), "-e", (prefix_ / "error.log").string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string output = (prefix_ / "output.log").string();
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, nginx.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return false;
  pid_ = pid;

  url_ = "http://127.0.0.1:" + std::to_string(port);
  httplib::Client client(url_);
  client.set_connection_timeout(1);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return false;
    }
    if (auto res = client.Get("/healthz"); res && res->status == 200) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  stop();
  return false;
}

void NginxBalancer::stop() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  int status = 0;
  for (int i = 0; i < 200; ++i) {
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
}

NginxBalancer::~NginxBalancer() {
  stop();
  std::error_code ec;
  fs::remove_all(prefix_, ec);
}

std::string NginxBalancer::error_log() const { return read_text(prefix_ / "error.log"); }
std::string NginxBalancer::access_log() const { return read_text(prefix_ / "access.log"); }

}  // namespace toond::test
