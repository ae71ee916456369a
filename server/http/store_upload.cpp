#include "http/store_upload.h"

#include <chrono>

namespace toond::http {
namespace {

// The label of toond_store_refusals_total for a refusal; empty for a
// failure that is not one (an I/O error).
std::string refusal_reason(scene::StoreError::Kind kind) {
  switch (kind) {
    case scene::StoreError::Kind::VolumeFull:
      return "volume_full";
    case scene::StoreError::Kind::FullOfModelsInUse:
      return "models_in_use";
    case scene::StoreError::Kind::LargerThanStore:
      return "larger_than_store";
    case scene::StoreError::Kind::Busy:
    case scene::StoreError::Kind::Failed:
      break;
  }
  return {};
}

}  // namespace

scene::ModelStore::PutResult store_upload(ServiceContext& context, const scene::Bundle& bundle,
                                          const scene::ImportChoices& choices) {
  const auto started = std::chrono::steady_clock::now();
  scene::ModelStore::PutResult result;
  try {
    result = context.store.put(bundle, context.limits.import, choices);
  } catch (const scene::StoreError& e) {
    const std::string reason = refusal_reason(e.kind());
    if (!reason.empty()) context.metrics.count_store_refusal(reason);
    throw;
  }
  // What was let go for the bound leaves this replica's memory and GPU now;
  // other replicas drop it at their next lookup, which asks the store.
  for (const std::string& id : result.evicted) context.renders.forget(id);
  // A bundle already stored was not imported again: nothing to time.
  if (result.created) {
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - started;
    context.metrics.observe_import(took.count(), bundle.total_bytes());
  }
  return result;
}

}  // namespace toond::http
