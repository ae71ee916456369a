#pragma once
#include <httplib.h>

#include "scene/bundle.h"

namespace toond::http {

// Collects a multipart body's file parts into a bundle: each part's filename
// is the file's path inside the bundle. Parts named in `skip` (e.g. the
// `params` part of a one-shot render) are left out. Throws RequestError when
// there is no file part or a name is unsafe.
scene::Bundle bundle_from_multipart(const httplib::Request& req, const std::string& skip = {});

}  // namespace toond::http
