#include "app/limit_options.h"

#include <cstdlib>

#include "app/flag_values.h"
#include "app/options.h"

namespace toond::app {
namespace {

constexpr unsigned long long kMaxSide = 4096;  // the schema's largest width/height

using Value = const std::string&;

const Flag kLimitFlags[] = {
    // httplib stops reading a multipart body beyond 1024 parts.
    {{"", "--max-bundle-files", "N", "files in one upload (default 256)"},
     [](Options& o, Value flag, Value v) { o.limits.max_bundle_files = parse_count(flag, v, 1, 1000); }},
    {{"", "--max-vertices", "N", "vertex positions in an uploaded model (default 10000000)"},
     [](Options& o, Value flag, Value v) { o.limits.import.max_vertices = parse_count(flag, v, 3, 1ull << 32); }},
    {{"", "--max-triangles", "N", "triangles in an uploaded model (default 10000000)"},
     [](Options& o, Value flag, Value v) { o.limits.import.max_triangles = parse_count(flag, v, 1, 1ull << 32); }},
    {{"", "--max-import-seconds", "S",
      "wall time one upload's import may take; past it the\n"
      "import is abandoned, nothing is stored (default 30)"},
     [](Options& o, Value flag, Value v) { o.limits.import.max_seconds = parse_seconds(flag, v, 0.001, 86400); }},
    {{"", "--max-texture-pixels", "N",
      "pixels of one texture, read from its header before\n"
      "decoding (default 67108864 = 8192x8192)"},
     [](Options& o, Value flag, Value v) {
       o.limits.import.max_texture_pixels = parse_count(flag, v, 1, 16384ull * 16384ull);
     }},
    {{"", "--max-output-pixels", "N",
      "width x height of a render, or of a whole sprite sheet\n"
      "(default 16777216 = 4096x4096)"},
     [](Options& o, Value flag, Value v) {
       o.limits.render.max_output_pixels = parse_count(flag, v, 16 * 16, kMaxSide * kMaxSide);
     }},
    {{"", "--max-samples", "N",
      "width x height x supersample^2 x msaa of a render as drawn\n"
      "(a depth, normal or id layer: one sample a pixel), times\n"
      "its frames for a sheet (default 134217728 = 4096x4096x8)"},
     [](Options& o, Value flag, Value v) {
       o.limits.render.max_samples = parse_count(flag, v, 16 * 16, 16384ull * 16384ull * 8ull);
     }},
    {{"", "--max-render-cost", "M",
      "predicted cost of a render in Msamples: surface layers x\n"
      "pixels x samples x passes, plus its triangles, the\n"
      "screen tiles they cross and the texels the edge pass\n"
      "reads, for all of a sheet's frames;\n"
      "refused before anything is drawn, with what would fit\n"
      "(default 5000, about 9 s of llvmpipe on 2 cores;\n"
      "0: no limit). The upload answer shows a model's layers"},
     [](Options& o, Value flag, Value v) {
       o.limits.render.max_render_cost = static_cast<double>(parse_count(flag, v, 0, 1ull << 40));
     }},
    {{"", "--max-lights", "N", "lights in a render (default 8)"},
     [](Options& o, Value flag, Value v) { o.limits.render.max_lights = parse_count(flag, v, 0, 8); }},
    {{"", "--max-objects", "N", "objects in a scene (default 16)"},
     [](Options& o, Value flag, Value v) { o.limits.render.max_objects = parse_count(flag, v, 1, 16); }},
    {{"", "--max-json-bytes", "N", "a JSON body or params part (default 1048576)"},
     [](Options& o, Value flag, Value v) { o.limits.max_json_bytes = parse_count(flag, v, 64, 1ull << 30); }},
    // The deepest parameter (objects[].transform.translate) sits 4 levels down.
    {{"", "--max-json-depth", "N", "nesting of arrays and objects in it (default 32)"},
     [](Options& o, Value flag, Value v) { o.limits.max_json_depth = parse_count(flag, v, 4, 10000); }},
};

const Flag kAccessFlags[] = {
    {{"", "--token", "T",
      "require \"Authorization: Bearer T\" on every route but\n"
      "/healthz (401 otherwise); default: the TOOND_TOKEN\n"
      "environment variable, else no token"},
     [](Options& o, Value flag, Value v) { o.access.token = non_empty(flag, v, "a non-empty value"); }},
    {{"", "--cors-origin", "O",
      "answer browsers from origin O (e.g. https://app.example)\n"
      "with CORS headers; repeatable; * allows any origin.\n"
      "Default: none (the page served by toond is same-origin)"},
     [](Options& o, Value flag, Value v) { o.access.cors_origins.push_back(non_empty(flag, v, "an origin or *")); }},
};

}  // namespace

std::span<const Flag> limit_flags() { return kLimitFlags; }

std::span<const Flag> access_flags() { return kAccessFlags; }

void apply_access_environment(http::AccessOptions& access) {
  if (!access.token.empty()) return;
  if (const char* token = std::getenv("TOOND_TOKEN"); token != nullptr && *token != '\0') access.token = token;
}

}  // namespace toond::app
