#pragma once
#include <httplib.h>

#include "http/request_limits.h"
#include "scene/reading/bundle.h"

namespace toond::http {

// Collects a multipart body's file parts into a bundle: each part's filename
// is the file's path inside the bundle. Parts named in `skip` (e.g. the
// `params` part of a one-shot render) are left out. Throws RequestError when
// there is no file part or a name is unsafe, LimitError (413) for more files
// than limits.max_bundle_files.
scene::Bundle bundle_from_multipart(const httplib::Request& req, const std::string& skip = {},
                                    const RequestLimits& limits = {});

}  // namespace toond::http
