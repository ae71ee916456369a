#pragma once
#include <stdexcept>
#include <string>
#include <system_error>

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
    Busy,               // another replica held the store's lock past StoreOptions::lock_wait
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

// An I/O failure as a client may read it: what could not be done and the
// system's reason, never a server path; the whole text goes to the log. A
// full volume (ENOSPC, EDQUOT) is Kind::VolumeFull, anything else Failed.
[[noreturn]] void throw_store_failure(const std::system_error& e, const std::string& what_failed);

}  // namespace toond::scene
