#pragma once
#include <string>

#include "request_error.h"

namespace toond {

// A request over one of the daemon's limits: 413 for sizes in bytes, 422 for
// counts. `limit` is the flag that sets it ("--max-lights"); the error body
// carries it as "limit" beside code "limit_exceeded".
class LimitError : public RequestError {
 public:
  LimitError(int status, std::string limit, const std::string& message, std::string path = {})
      : RequestError(status, "limit_exceeded", message, std::move(path)), limit_(std::move(limit)) {}
  const std::string& limit() const { return limit_; }

 private:
  std::string limit_;
};

}  // namespace toond
