#include "app/limit_options.h"

#include <cstdlib>
#include <stdexcept>

namespace toond::app {
namespace {

unsigned long long parse_count(const std::string& flag, const std::string& text, unsigned long long min,
                               unsigned long long max) {
  std::size_t used = 0;
  unsigned long long v = 0;
  try {
    if (!text.empty() && text[0] != '-') v = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || v < min || v > max) {
    throw std::invalid_argument(flag + " expects an integer in " + std::to_string(min) + ".." + std::to_string(max) +
                                ", got '" + text + "'");
  }
  return v;
}

double parse_seconds(const std::string& flag, const std::string& text, double min, double max) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(v >= min && v <= max)) {
    throw std::invalid_argument(flag + " expects seconds in " + std::to_string(min).substr(0, 5) + ".." +
                                std::to_string(static_cast<long long>(max)) + ", got '" + text + "'");
  }
  return v;
}

constexpr unsigned long long kMaxSide = 4096;  // the schema's largest width/height

}  // namespace

bool parse_limit_option(const std::vector<std::string>& args, std::size_t& i, http::RequestLimits& limits,
                        http::AccessOptions& access) {
  const std::string& flag = args[i];
  const auto value = [&]() -> const std::string& {
    if (i + 1 >= args.size()) throw std::invalid_argument(flag + " needs a value");
    return args[++i];
  };
  const auto count = [&](unsigned long long min, unsigned long long max) {
    return parse_count(flag, value(), min, max);
  };
  if (flag == "--max-bundle-files") {
    // httplib stops reading a multipart body beyond 1024 parts.
    limits.max_bundle_files = count(1, 1000);
  } else if (flag == "--max-vertices") {
    limits.import.max_vertices = count(3, 1ull << 32);
  } else if (flag == "--max-triangles") {
    limits.import.max_triangles = count(1, 1ull << 32);
  } else if (flag == "--max-import-seconds") {
    limits.import.max_seconds = parse_seconds(flag, value(), 0.001, 86400);
  } else if (flag == "--max-texture-pixels") {
    limits.import.max_texture_pixels = count(1, 16384ull * 16384ull);
  } else if (flag == "--max-output-pixels") {
    limits.render.max_output_pixels = count(16 * 16, kMaxSide * kMaxSide);
  } else if (flag == "--max-samples") {
    limits.render.max_samples = count(16 * 16, 16384ull * 16384ull * 8ull);
  } else if (flag == "--max-lights") {
    limits.render.max_lights = count(0, 8);
  } else if (flag == "--max-objects") {
    limits.render.max_objects = count(1, 16);
  } else if (flag == "--max-json-bytes") {
    limits.max_json_bytes = count(64, 1ull << 30);
  } else if (flag == "--max-json-depth") {
    // The deepest parameter (objects[].transform.translate) sits 4 levels down.
    limits.max_json_depth = count(4, 10000);
  } else if (flag == "--token") {
    access.token = value();
    if (access.token.empty()) throw std::invalid_argument("--token needs a non-empty value");
  } else if (flag == "--cors-origin") {
    access.cors_origins.push_back(value());
    if (access.cors_origins.back().empty()) throw std::invalid_argument("--cors-origin needs an origin or *");
  } else {
    return false;
  }
  return true;
}

std::string limit_usage() {
  return R"(Limits (over one: 413 for bytes, 422 for counts, {"error":{"code":"limit_exceeded",
"limit":"--max-...",...}}):
  --max-bundle-files N   files in one upload (default 256)
  --max-vertices N       vertex positions in an uploaded model (default 10000000)
  --max-triangles N      triangles in an uploaded model (default 10000000)
  --max-import-seconds S wall time one upload's import may take; past it the
                         import is abandoned, nothing is stored (default 30)
  --max-texture-pixels N pixels of one texture, read from its header before
                         decoding (default 67108864 = 8192x8192)
  --max-output-pixels N  width x height of a render, or of a whole sprite sheet
                         (default 16777216 = 4096x4096)
  --max-samples N        width x height x supersample^2 x msaa of a render, times
                         its frames for a sheet (default 134217728 = 4096x4096x8)
  --max-lights N         lights in a render (default 8)
  --max-objects N        objects in a scene (default 16)
  --max-json-bytes N     a JSON body or params part (default 1048576)
  --max-json-depth N     nesting of arrays and objects in it (default 32)
Access:
  --token T              require "Authorization: Bearer T" on every route but
                         /healthz (401 otherwise); default: the TOOND_TOKEN
                         environment variable, else no token
  --cors-origin O        answer browsers from origin O (e.g. https://app.example)
                         with CORS headers; repeatable; * allows any origin.
                         Default: none (the page served by toond is same-origin)
)";
}

void apply_access_environment(http::AccessOptions& access) {
  if (!access.token.empty()) return;
  if (const char* token = std::getenv("TOOND_TOKEN"); token != nullptr && *token != '\0') access.token = token;
}

}  // namespace toond::app
