#include "support/prometheus_text.h"

#include <chrono>
#include <sstream>
#include <thread>

namespace toond::test {

std::optional<double> sample_value(const std::string& exposition, const std::string& series) {
  std::istringstream lines(exposition);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.size() > series.size() && line.compare(0, series.size(), series) == 0 && line[series.size()] == ' ') {
      return std::stod(line.substr(series.size() + 1));
    }
  }
  return std::nullopt;
}

double counter_value(const std::string& exposition, const std::string& series) {
  return sample_value(exposition, series).value_or(0.0);
}

std::string scrape_when(httplib::Client& client, const std::function<bool(const std::string&)>& ready) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  std::string text;
  for (;;) {
    if (auto res = client.Get("/metrics"); res && res->status == 200) text = res->body;
    if (ready(text) || std::chrono::steady_clock::now() > deadline) return text;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

std::string request_series(const std::string& method, const std::string& route, int status) {
  return "toond_http_requests_total{method=\"" + method + "\",route=\"" + route + "\",status=\"" +
         std::to_string(status) + "\"}";
}

}  // namespace toond::test
