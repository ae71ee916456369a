#pragma once
// Sends bytes to the daemon exactly as given (malformed HTTP, broken
// multipart) and reads what comes back, which no HTTP client library would.
#include <string>

namespace toond::test {

struct RawAnswer {
  int status = 0;  // 0: the connection closed without a status line
  std::string head;
  std::string body;
};

// `url` is the daemon's "http://127.0.0.1:PORT". Reads until the daemon
// closes the connection or `timeout_s` passes. `hang_up`: close the sending
// side after the bytes (a client that goes away mid-request); httplib may
// then drop even a complete request unanswered, so it is off by default.
RawAnswer send_raw(const std::string& url, const std::string& bytes, int timeout_s = 20, bool hang_up = false);

}  // namespace toond::test
