#include "scene/store/store_error.h"

#include <cerrno>

namespace toond::scene {
namespace {

bool volume_full(const std::error_code& code) {
  const std::error_condition condition = code.default_error_condition();
  return condition == std::errc::no_space_on_device ||
         condition == std::error_condition(EDQUOT, std::generic_category());
}

}  // namespace

void throw_store_failure(const std::system_error& e, const std::string& what_failed) {
  if (volume_full(e.code())) {
    throw StoreError(StoreError::Kind::VolumeFull,
                     "the volume the models are stored on is full (" + e.code().message() + ")", e.what());
  }
  throw StoreError(StoreError::Kind::Failed, what_failed + " (" + e.code().message() + ")", e.what());
}

}  // namespace toond::scene
