#include "http/bundle_upload.h"

#include "limit_error.h"
#include "request_error.h"
#include "scene/reading/import_error.h"

namespace toond::http {

scene::Bundle bundle_from_multipart(const httplib::Request& req, const std::string& skip, const RequestLimits& limits) {
  if (!req.is_multipart_form_data()) {
    throw RequestError(415, "not_multipart", "expected multipart/form-data with one part per bundle file");
  }
  const std::size_t files = req.files.size() - (skip.empty() ? 0 : req.files.count(skip));
  if (files > limits.max_bundle_files) {
    throw LimitError(413, "--max-bundle-files",
                     "the upload holds " + std::to_string(files) +
                         " files, more than the limit --max-bundle-files = " + std::to_string(limits.max_bundle_files));
  }
  scene::Bundle bundle;
  for (const auto& [name, part] : req.files) {
    if (!skip.empty() && name == skip) continue;
    const std::string& path = part.filename.empty() ? part.name : part.filename;
    try {
      bundle.add(path, part.content);
    } catch (const scene::ImportError& e) {
      throw RequestError(400, "bad_file_name", e.what(), e.file());
    }
  }
  if (bundle.empty()) {
    throw RequestError(400, "empty_bundle", "the upload holds no file parts");
  }
  return bundle;
}

}  // namespace toond::http
