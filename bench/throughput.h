#pragma once
// Load: requests per second and latency percentiles with 1, 4 and 16
// clients rendering at once, each over its own keep-alive connection.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace toond::bench {

struct LoadLevel {
  int clients = 0;
  std::size_t requests = 0;
  std::size_t failures = 0;  // non-200 answers (a full queue answers 503)
  // Why they failed: "HTTP 503 busy", "no answer (Read)", ... → count.
  std::map<std::string, std::size_t> failure_kinds;
  double seconds = 0;
  double requests_per_s = 0;
  double p50_ms = 0;
  double p99_ms = 0;
};

// Each request varies the camera yaw by a hair so no two are identical and
// a result cache cannot answer them.
std::vector<LoadLevel> run_throughput(const std::string& url, const nlohmann::json& params,
                                      const std::vector<int>& clients, double seconds_per_level);
nlohmann::json throughput_json(const std::vector<LoadLevel>& levels);

}  // namespace toond::bench
