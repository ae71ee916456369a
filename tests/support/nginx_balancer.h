#pragma once
// Debian's nginx as a load balancer in front of toond replicas, for the
// scale-out test: a temporary prefix holding the config, pid, logs and temp
// folders, running as the current user in the foreground (no daemon, no
// master/worker split), listening on a free 127.0.0.1 port. Its config
// includes the shipped routing snippets of docker/nginx/, so the test runs
// the same hashing and retry rules as the compose deployment.
#include <filesystem>
#include <string>
#include <vector>

namespace toond::test {

class NginxBalancer {
 public:
  // The nginx executable (PATH, then /usr/sbin); empty when not installed.
  static std::string find_nginx();

  // `upstreams`: "host:port" of each replica. Returns once a GET /healthz
  // through the balancer answers 200; throws with nginx's error log when it
  // does not start.
  NginxBalancer(const std::string& nginx, const std::vector<std::string>& upstreams,
                const std::filesystem::path& snippet_dir);
  ~NginxBalancer();
  NginxBalancer(const NginxBalancer&) = delete;
  NginxBalancer& operator=(const NginxBalancer&) = delete;

  const std::string& url() const { return url_; }
  std::string error_log() const;
  std::string access_log() const;

 private:
  bool start(const std::string& nginx, int port);
  void stop();

  std::filesystem::path prefix_;
  std::string url_;
  int pid_ = -1;
};

}  // namespace toond::test
