#include "http/request_limits.h"

#include <string>

#include "limit_error.h"
#include "request_error.h"

namespace toond::http {

std::size_t json_nesting_depth(std::string_view text, std::size_t stop_at) {
  std::size_t depth = 0;
  std::size_t deepest = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > deepest) deepest = depth;
      if (deepest > stop_at) return deepest;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

void check_request_counts(const nlohmann::json& request, const RequestLimits& limits) {
  if (!request.is_object()) return;
  const auto check = [&](const char* field, std::size_t most, const char* flag) {
    const auto it = request.find(field);
    if (it == request.end() || !it->is_array() || it->size() <= most) return;
    throw LimitError(422, flag,
                     std::string("/") + field + " has " + std::to_string(it->size()) +
                         " entries, more than the limit " + flag + " = " + std::to_string(most),
                     std::string("/") + field);
  };
  check("lights", limits.render.max_lights, "--max-lights");
  check("objects", limits.render.max_objects, "--max-objects");
}

nlohmann::json limits_document(const RequestLimits& limits) {
  return {
      {"--max-upload-bytes", limits.max_upload_bytes},
      {"--max-bundle-files", limits.max_bundle_files},
      {"--max-json-bytes", limits.max_json_bytes},
      {"--max-json-depth", limits.max_json_depth},
      {"--max-vertices", limits.import.max_vertices},
      {"--max-triangles", limits.import.max_triangles},
      {"--max-texture-pixels", limits.import.max_texture_pixels},
      {"--max-import-seconds", limits.import.max_seconds},
      {"--max-output-pixels", limits.render.max_output_pixels},
      {"--max-samples", limits.render.max_samples},
      {"--max-lights", limits.render.max_lights},
      {"--max-objects", limits.render.max_objects},
      {"--max-render-cost", limits.render.max_render_cost},
  };
}

nlohmann::json parse_limited_json(std::string_view text, const RequestLimits& limits, std::string_view where) {
  if (text.empty()) return nlohmann::json::object();
  if (text.size() > limits.max_json_bytes) {
    throw LimitError(
        413, "--max-json-bytes",
        std::string(where) + " is " + std::to_string(text.size()) +
            " bytes of JSON, more than the limit --max-json-bytes = " + std::to_string(limits.max_json_bytes));
  }
  if (json_nesting_depth(text, limits.max_json_depth) > limits.max_json_depth) {
    throw LimitError(422, "--max-json-depth",
                     std::string(where) + " nests arrays and objects more than the limit --max-json-depth = " +
                         std::to_string(limits.max_json_depth) + " levels deep");
  }
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw RequestError(400, "malformed_json",
                       std::string(where) + " is not valid JSON (byte " + std::to_string(e.byte) + ")", "");
  } catch (const nlohmann::json::exception& e) {
    // e.g. out_of_range 406: a number beyond double's range ("1e400").
    throw RequestError(400, "malformed_json", std::string(where) + " is not usable JSON: " + e.what(), "");
  }
}

}  // namespace toond::http
