#pragma once
// Reads samples out of a Prometheus text exposition (GET /metrics).
#include <functional>
#include <optional>
#include <string>

#include <httplib.h>

namespace toond::test {

// The value of the sample whose series (metric name plus its label set,
// written exactly as the exposition writes it, e.g.
// `toond_http_requests_total{method="POST",route="/render",status="200"}`)
// is `series`; nullopt when there is no such line.
std::optional<double> sample_value(const std::string& exposition, const std::string& series);

// The same, 0 when the series is absent (a counter before its first event).
double counter_value(const std::string& exposition, const std::string& series);

// GET /metrics until `ready` holds for its text (5 s at most), returning the
// last text. toond counts a request just after sending its answer, so a
// scrape right after an answer may not count it yet.
std::string scrape_when(httplib::Client& client, const std::function<bool(const std::string&)>& ready);

// The series name of toond's request counter for one method, route and status.
std::string request_series(const std::string& method, const std::string& route, int status);

}  // namespace toond::test
