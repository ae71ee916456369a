#pragma once
#include <stdexcept>
#include <string>

namespace toond::scene {

// A bundle that cannot become a model. `file` names the bundle file at fault
// (empty when the bundle as a whole is wrong), so the HTTP layer can report it
// as the error's path.
class ImportError : public std::runtime_error {
 public:
  ImportError(std::string file, const std::string& message) : std::runtime_error(message), file_(std::move(file)) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace toond::scene
