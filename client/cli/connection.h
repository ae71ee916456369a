#pragma once
// One HTTP client to toond with the CLI's timeouts and User-Agent, and the
// helpers the verbs share for sending bundles and reporting failures.
#include <httplib.h>

#include <ctime>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bundle_scan.h"
#include "cli_args.h"

namespace toond::cli {

inline constexpr time_t kConnectTimeoutS = 5;
// A large model at 4096² with 8× MSAA on llvmpipe, behind a queue, can take
// minutes; the daemon answers 503 itself when its queue is full.
inline constexpr time_t kReadTimeoutS = 300;

class Connection {
 public:
  explicit Connection(const std::string& server);

  httplib::Result get(const std::string& path);
  httplib::Result post_json(const std::string& path, const nlohmann::json& body);
  httplib::Result post_multipart(const std::string& path, const httplib::MultipartFormDataItems& items);

  // Why no answer came, as one line ("cannot reach toond at URL (...)").
  std::string describe_failure(const httplib::Result& result) const;
  // Prints describe_failure and returns the exit status for it.
  int network_failure(const httplib::Result& result) const;

  const std::string& server() const { return server_; }

 private:
  std::string server_;
  ServerUrl url_;
  httplib::Client client_;
};

// Prints the daemon's error answer and returns exit status 1.
int error_reply(const httplib::Response& response);

void print_warnings(const std::vector<std::string>& warnings);

// One multipart "file" part per bundle file.
httplib::MultipartFormDataItems bundle_parts(const BundleScan& scan);

// "3 files (1.1 MB): spot.obj spot.mtl spot_texture.png"
std::string bundle_summary(const BundleScan& scan);

}  // namespace toond::cli
