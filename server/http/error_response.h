#pragma once
// The one place that turns failures into HTTP answers:
//   {"error":{"code":…,"message":…,"path":…}}
// Request errors keep their status; GPU failures are 500; a full render
// queue is 503 with Retry-After; anything else is a logged 500.
#include <exception>

#include <httplib.h>

namespace toond::http {

void write_error(httplib::Response& res, int status, const std::string& code,
                 const std::string& message, const std::string& path = {});

// Maps the exception in flight (or `ep`) to a response.
void write_exception(httplib::Response& res, std::exception_ptr ep);

}  // namespace toond::http
