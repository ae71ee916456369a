#pragma once
// The one place that turns failures into HTTP answers:
//   {"error":{"code":…,"message":…,"path":…}}
// Request errors keep their status; GPU failures are 500; a full render
// queue is 503 with Retry-After; a full model store is 507 storage_full;
// anything else is a logged 500. No message names a server path.
#include <exception>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace toond::http {

void write_error(httplib::Response& res, int status, const std::string& code, const std::string& message,
                 const std::string& path = {});

// An error over one of the daemon's limits: `limit` names the flag.
void write_limit_error(httplib::Response& res, int status, const std::string& code, const std::string& limit,
                       const std::string& message, const std::string& path = {});

// JSON text of an answer body; invalid UTF-8 in it becomes U+FFFD.
std::string dump_for_client(const nlohmann::json& body);

// Maps the exception in flight (or `ep`) to a response.
void write_exception(httplib::Response& res, std::exception_ptr ep);

}  // namespace toond::http
