#pragma once
#include <stdexcept>
#include <string>

namespace toond::scene {

// Why the model store could not keep (or read) a model. what() is for the
// client and names no server path; detail() is for the daemon's log and
// may. Which flag sets the bound is the HTTP layer's business, as with
// ImportLimitError.
class StoreError : public std::runtime_error {
 public:
  enum class Kind {
    VolumeFull,         // the file system said no space (ENOSPC, EDQUOT); nothing was kept
    FullOfModelsInUse,  // at the bound, and every model that could go is held by a render
    LargerThanStore,    // this one model is larger than the whole bound
    Failed,             // any other I/O error
  };
  StoreError(Kind kind, const std::string& message, std::string detail = {})
      : std::runtime_error(message), kind_(kind), detail_(std::move(detail)) {}
  Kind kind() const { return kind_; }
  const std::string& detail() const { return detail_; }

 private:
  Kind kind_;
  std::string detail_;
};

}  // namespace toond::scene
