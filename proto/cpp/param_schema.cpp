#include "param_schema.h"

#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include <cerrno>
#include <charconv>
#include <cstdlib>

#include "toond_proto_files.h"

namespace toond::proto {
namespace {

using nlohmann::json;

std::string escape_segment(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

// The sub-schema describing property `name` of an object schema, or the
// items schema of an array schema; nullptr when the schema has none.
const json* child_schema(const json& schema, const std::string& name) {
  if (auto props = schema.find("properties"); props != schema.end()) {
    if (auto p = props->find(name); p != props->end()) return &*p;
  }
  return nullptr;
}

const json* items_schema(const json& schema) {
  auto items = schema.find("items");
  return items != schema.end() && items->is_object() ? &*items : nullptr;
}

// Unknown names are found by walking the schema itself, so the error can point
// at the unknown field rather than at the object that contains it.
void check_known_fields(const json& schema, const json& value, std::vector<std::string>& path) {
  if (value.is_object() && schema.contains("properties")) {
    for (const auto& [key, sub] : value.items()) {
      path.push_back(key);
      const json* child = child_schema(schema, key);
      if (!child && schema.value("additionalProperties", true) == false) {
        throw RequestError(400, "unknown_parameter", "unknown parameter '" + key + "'",
                           json_pointer(path));
      }
      if (child) check_known_fields(*child, sub, path);
      path.pop_back();
    }
  } else if (value.is_array()) {
    if (const json* items = items_schema(schema)) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        path.push_back(std::to_string(i));
        check_known_fields(*items, value[i], path);
        path.pop_back();
      }
    }
  }
}

void fill_defaults(const json& schema, json& value) {
  if (value.is_object()) {
    if (auto props = schema.find("properties"); props != schema.end()) {
      for (const auto& [key, sub] : props->items()) {
        if (!value.contains(key) && sub.contains("default")) value[key] = sub["default"];
        if (value.contains(key)) fill_defaults(sub, value[key]);
      }
    }
  } else if (value.is_array()) {
    if (const json* items = items_schema(schema)) {
      for (auto& element : value) fill_defaults(*items, element);
    }
  }
}

// valijson names a context step "[outline]" or "[0]"; the root is "<root>".
std::vector<std::string> context_to_segments(const std::vector<std::string>& context) {
  std::vector<std::string> out;
  for (const auto& step : context) {
    if (step.size() >= 2 && step.front() == '[' && step.back() == ']') {
      out.push_back(step.substr(1, step.size() - 2));
    }
  }
  return out;
}

std::string describe_limits(const json& schema) {
  std::string out;
  if (schema.contains("enum")) out += " (one of " + schema["enum"].dump() + ")";
  if (schema.contains("minimum") || schema.contains("maximum")) {
    out += " (range " + (schema.contains("minimum") ? schema["minimum"].dump() : "") + ".." +
           (schema.contains("maximum") ? schema["maximum"].dump() : "") + ")";
  }
  return out;
}

const json* schema_at(const json& root, const std::vector<std::string>& segments) {
  const json* s = &root;
  for (const auto& seg : segments) {
    const json* next = child_schema(*s, seg);
    if (!next) next = items_schema(*s);
    if (!next) return nullptr;
    s = next;
  }
  return s;
}

}  // namespace

std::string json_pointer(const std::vector<std::string>& segments) {
  std::string out;
  for (const auto& s : segments) out += "/" + escape_segment(s);
  return out;
}

struct ParamSchema::Compiled {
  valijson::Schema schema;
};

ParamSchema::ParamSchema(const nlohmann::json& document)
    : document_(document), compiled_(std::make_unique<Compiled>()) {
  valijson::SchemaParser parser;
  valijson::adapters::NlohmannJsonAdapter adapter(document_);
  parser.populateSchema(adapter, compiled_->schema);
}

ParamSchema::~ParamSchema() = default;

const ParamSchema& ParamSchema::render_params() {
  static const ParamSchema schema(
      json::parse(toond::proto_files::find("render-params.schema.json")));
  return schema;
}

void ParamSchema::validate(const nlohmann::json& request) const {
  if (!request.is_object()) {
    throw RequestError(400, "invalid_parameter", "render parameters must be a JSON object", "");
  }
  std::vector<std::string> path;
  check_known_fields(document_, request, path);

  valijson::Validator validator;
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter target(request);
  if (validator.validate(compiled_->schema, target, &results)) return;

  // valijson reports the chain from the root down; the deepest entry is the
  // one that names the actual field.
  valijson::ValidationResults::Error deepest;
  valijson::ValidationResults::Error error;
  std::size_t best_depth = 0;
  bool first = true;
  while (results.popError(error)) {
    if (first || error.context.size() > best_depth) {
      deepest = error;
      best_depth = error.context.size();
      first = false;
    }
  }
  const auto segments = context_to_segments(deepest.context);
  std::string field = segments.empty() ? std::string("request") : json_pointer(segments);
  std::string limits;
  if (const json* s = schema_at(document_, segments)) limits = describe_limits(*s);
  throw RequestError(400, "invalid_parameter",
                     field + ": " + deepest.description + limits, json_pointer(segments));
}

nlohmann::json ParamSchema::validate_and_complete(const nlohmann::json& request) const {
  validate(request);
  json completed = request;
  fill_defaults(document_, completed);
  return completed;
}

void ParamSchema::set_from_text(nlohmann::json& params, std::string_view dotted,
                                std::string_view text) const {
  std::vector<std::string> segments;
  std::string key(dotted);
  for (std::size_t start = 0; start <= key.size();) {
    std::size_t dot = key.find('.', start);
    if (dot == std::string::npos) dot = key.size();
    segments.push_back(key.substr(start, dot - start));
    start = dot + 1;
  }
  const json* schema = &document_;
  std::vector<const json*> chain;  // the schema of each segment
  for (const auto& seg : segments) {
    const json* next = child_schema(*schema, seg);
    if (!next) {
      const json* items = items_schema(*schema);
      bool is_index = !seg.empty() && seg.find_first_not_of("0123456789") == std::string::npos;
      next = (items && is_index) ? items : nullptr;
    }
    if (!next) {
      throw RequestError(400, "unknown_parameter",
                         "unknown parameter '" + key + "' (see GET /schema or proto/)",
                         json_pointer(segments));
    }
    schema = next;
    chain.push_back(schema);
  }

  const std::string type = schema->value("type", "");
  const std::string raw(text);
  json value;
  auto fail = [&](const std::string& why) {
    throw RequestError(400, "invalid_parameter", key + "=" + raw + ": " + why,
                       json_pointer(segments));
  };
  if (type == "string") {
    value = raw;
  } else if (type == "boolean") {
    if (raw == "true" || raw == "1" || raw == "on") value = true;
    else if (raw == "false" || raw == "0" || raw == "off") value = false;
    else fail("expected true or false");
  } else if (type == "integer") {
    long long v = 0;
    auto [ptr, ec] = std::from_chars(raw.data(), raw.data() + raw.size(), v);
    if (ec != std::errc() || ptr != raw.data() + raw.size()) fail("expected an integer");
    value = v;
  } else if (type == "number") {
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(raw.c_str(), &end);
    if (raw.empty() || end != raw.c_str() + raw.size() || errno == ERANGE) fail("expected a number");
    value = v;
  } else {
    // Arrays and objects are given as JSON: --set background=[1,1,1]. A
    // field that may be one of several types (outline.method: a name or a
    // list of names) takes JSON when the text is JSON, else the plain text.
    value = json::parse(raw, nullptr, false);
    if (value.is_discarded()) {
      if (!type.empty()) fail("expected JSON for a " + type);
      value = raw;
    }
  }

  json* slot = &params;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& seg = segments[i];
    if (slot->is_array()) {
      std::size_t index = std::stoul(seg);
      if (index > slot->size()) fail("array index " + seg + " skips elements");
      if (index == slot->size()) slot->push_back(json::object());
      slot = &(*slot)[index];
    } else {
      bool next_is_index = i + 1 < segments.size() &&
                           segments[i + 1].find_first_not_of("0123456789") == std::string::npos;
      if (!slot->contains(seg)) {
        // `lights.0.intensity=2` means "the default light, brighter", not a
        // light with nothing but an intensity (which lacks its required
        // type): an absent array starts as the schema's default.
        const json& node = *chain[i];
        if (next_is_index && node.contains("default") && node["default"].is_array()) {
          (*slot)[seg] = node["default"];
        } else {
          (*slot)[seg] = next_is_index ? json::array() : json::object();
        }
      }
      slot = &(*slot)[seg];
    }
  }
  *slot = value;
}

}  // namespace toond::proto
