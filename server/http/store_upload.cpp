#include "http/store_upload.h"

#include <chrono>

namespace toond::http {

scene::ModelStore::PutResult store_upload(ServiceContext& context, const scene::Bundle& bundle,
                                          const scene::ImportChoices& choices) {
  const auto started = std::chrono::steady_clock::now();
  scene::ModelStore::PutResult result = context.store.put(bundle, context.limits.import, choices);
  // A bundle already stored was not imported again: nothing to time.
  if (result.created) {
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - started;
    context.metrics.observe_import(took.count(), bundle.total_bytes());
  }
  return result;
}

}  // namespace toond::http
