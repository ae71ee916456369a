#include "throughput.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>

#include <httplib.h>

#include "stats.h"

namespace toond::bench {

std::vector<LoadLevel> run_throughput(const std::string& url, const nlohmann::json& params,
                                      const std::vector<int>& clients, double seconds_per_level) {
  using Clock = std::chrono::steady_clock;
  std::vector<LoadLevel> levels;
  std::atomic<long> counter{0};
  for (int n : clients) {
    std::mutex mutex;
    std::vector<double> latencies;
    std::size_t failures = 0;
    std::map<std::string, std::size_t> failure_kinds;
    const auto start = Clock::now();
    const auto deadline = start + std::chrono::duration<double>(seconds_per_level);
    std::vector<std::thread> threads;
    for (int c = 0; c < n; ++c) {
      threads.emplace_back([&] {
        httplib::Client client(url);
        client.set_read_timeout(120);
        client.set_keep_alive(true);
        // Like a browser: a request's body does not wait for the ACK of its headers.
        client.set_tcp_nodelay(true);
        std::vector<double> mine;
        std::size_t failed = 0;
        std::map<std::string, std::size_t> why;
        while (Clock::now() < deadline) {
          nlohmann::json p = params;
          p["camera"]["yaw"] = 1e-3 * static_cast<double>(counter.fetch_add(1) % 1000);
          const auto t0 = Clock::now();
          auto res = client.Post("/render", {{"Cache-Control", "no-cache"}}, p.dump(), "application/json");
          const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
          if (res && res->status == 200) {
            mine.push_back(ms);
            continue;
          }
          ++failed;
          if (!res) {
            // How long it waited tells a stale kept-alive connection
            // (at once) from a timeout (seconds) when one turns up.
            char waited[32];
            std::snprintf(waited, sizeof waited, "%.0f ms", ms);
            ++why["no answer (" + httplib::to_string(res.error()) + ") after " + waited];
          } else {
            std::string code;
            try {
              code = nlohmann::json::parse(res->body).at("error").at("code").get<std::string>();
            } catch (const std::exception&) {
            }
            ++why["HTTP " + std::to_string(res->status) + (code.empty() ? "" : " " + code)];
          }
        }
        std::lock_guard lock(mutex);
        latencies.insert(latencies.end(), mine.begin(), mine.end());
        failures += failed;
        for (const auto& [kind, count] : why) failure_kinds[kind] += count;
      });
    }
    for (auto& t : threads) t.join();
    LoadLevel level;
    level.clients = n;
    level.requests = latencies.size();
    level.failures = failures;
    level.failure_kinds = failure_kinds;
    level.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    level.requests_per_s = static_cast<double>(level.requests) / level.seconds;
    level.p50_ms = percentile(latencies, 0.50);
    level.p99_ms = percentile(latencies, 0.99);
    std::fprintf(stderr, "  %2d clients: %6.1f req/s  p50 %7.1f ms  p99 %7.1f ms  (%zu ok, %zu failed)\n", n,
                 level.requests_per_s, level.p50_ms, level.p99_ms, level.requests, level.failures);
    for (const auto& [kind, count] : failure_kinds) std::fprintf(stderr, "      %zu × %s\n", count, kind.c_str());
    levels.push_back(level);
  }
  return levels;
}

nlohmann::json throughput_json(const std::vector<LoadLevel>& levels) {
  nlohmann::json out = nlohmann::json::array();
  for (const LoadLevel& l : levels) {
    out.push_back({{"clients", l.clients},
                   {"requests", l.requests},
                   {"failures", l.failures},
                   {"failure_kinds", l.failure_kinds},
                   {"seconds", l.seconds},
                   {"requests_per_s", l.requests_per_s},
                   {"p50_ms", l.p50_ms},
                   {"p99_ms", l.p99_ms}});
  }
  return out;
}

}  // namespace toond::bench
