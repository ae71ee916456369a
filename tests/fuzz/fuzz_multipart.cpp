// libFuzzer target: the parts of a multipart upload (as httplib hands them
// to the routes: part name, filename, bytes) through bundle_from_multipart.
// Refusals are fine; a bundle path that could leave the bundle folder once
// the store writes it (absolute, "..", "\", NUL, control characters, not
// UTF-8, not normalised) is a finding. The byte-level multipart parser is
// httplib's (Debian's shared library, not instrumented here).
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <httplib.h>

#include "bundle_paths/bundle_path.h"
#include "fuzz_input.h"
#include "http/bundle_upload.h"
#include "request_error.h"

namespace {

[[noreturn]] void finding(const std::string& path, const char* what) {
  std::fprintf(stderr, "fuzz_multipart: bundle path '%s': %s\n", path.c_str(), what);
  std::abort();
}

bool valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t extra = c < 0x80             ? 0
                              : (c & 0xe0) == 0xc0 ? 1
                              : (c & 0xf0) == 0xe0 ? 2
                              : (c & 0xf8) == 0xf0 ? 3
                                                   : 9;
    if (extra == 9 || i + extra >= s.size() + (extra == 0 ? 1 : 0)) return false;
    for (std::size_t k = 1; k <= extra; ++k) {
      if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
    }
    i += extra + 1;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  httplib::Request req;
  req.set_header("Content-Type", "multipart/form-data; boundary=x");
  for (auto& [header, content] : toond::fuzz::split_files(data, size)) {
    // "name|filename": the part name before the first '|'; without one the
    // name is "file" (as the CLI sends) or the whole line is a `params` part.
    const auto bar = header.find('|');
    httplib::MultipartFormData part;
    part.name = bar == std::string::npos ? (header == "params" ? "params" : "file") : header.substr(0, bar);
    part.filename = bar == std::string::npos ? header : header.substr(bar + 1);
    part.content = std::move(content);
    req.files.emplace(part.name, std::move(part));
  }
  toond::http::RequestLimits limits;
  limits.max_bundle_files = 32;
  toond::scene::Bundle bundle;
  try {
    bundle = toond::http::bundle_from_multipart(req, "params", limits);
  } catch (const toond::RequestError&) {
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_multipart: unexpected exception: %s\n", e.what());
    std::abort();
  }
  namespace fs = std::filesystem;
  const fs::path root = "/srv/toond/models/x/files";
  for (const auto& [path, content] : bundle.files()) {
    if (path.empty() || path.front() == '/') finding(path, "empty or absolute");
    if (path.find('\\') != std::string::npos || path.find('\0') != std::string::npos) finding(path, "\\ or NUL");
    for (const char c : path) {
      if (static_cast<unsigned char>(c) < 0x20) finding(path, "control character");
    }
    if (!valid_utf8(path)) finding(path, "not UTF-8");
    const bool letter = !path.empty() && ((path[0] >= 'A' && path[0] <= 'Z') || (path[0] >= 'a' && path[0] <= 'z'));
    if (letter && path.size() >= 2 && path[1] == ':') finding(path, "drive letter");
    if (toond::bundle_paths::normalize_path(path) != path) finding(path, "not normalised");
    const fs::path target = (root / path).lexically_normal();
    const auto rel = target.lexically_relative(root);
    if (rel.empty() || *rel.begin() == "..") finding(path, "leaves the bundle folder");
  }
  return 0;
}
