#pragma once
#include <stdexcept>
#include <string>

namespace toond {

// An error the client caused. Carries what the HTTP error body needs:
// status, a stable machine-readable code, a message for people, and `path`,
// a JSON pointer into the request ("/outline/width") or the bundle file at
// fault ("textures/spot.png"), empty when nothing more precise applies.
class RequestError : public std::runtime_error {
 public:
  RequestError(int status, std::string code, const std::string& message, std::string path = {})
      : std::runtime_error(message), status_(status), code_(std::move(code)), path_(std::move(path)) {}
  int status() const { return status_; }
  const std::string& code() const { return code_; }
  const std::string& path() const { return path_; }

 private:
  int status_;
  std::string code_;
  std::string path_;
};

}  // namespace toond
