#pragma once
// An uploaded bundle into the model store, the one way both upload routes
// (POST /models and a multipart POST /render) take: a new model's import is
// timed and sized for /metrics, the store's refusals counted, and the models
// it let go for its bound forgotten by this replica.
#include "http/service_context.h"
#include "scene/reading/bundle.h"
#include "scene/store/model_store.h"

namespace toond::http {

scene::ModelStore::PutResult store_upload(ServiceContext& context, const scene::Bundle& bundle,
                                          const scene::ImportChoices& choices = {});

}  // namespace toond::http
