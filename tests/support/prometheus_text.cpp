#include "support/prometheus_text.h"

#include <sstream>

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

std::string request_series(const std::string& method, const std::string& route, int status) {
  return "toond_http_requests_total{method=\"" + method + "\",route=\"" + route + "\",status=\"" +
         std::to_string(status) + "\"}";
}

}  // namespace toond::test
