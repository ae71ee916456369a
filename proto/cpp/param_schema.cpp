#include "param_schema.h"

#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <vector>

#include "toond_proto_files.h"

namespace toond::proto {
namespace {

using nlohmann::json;

std::string escape_segment(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
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

// The schemas a field may take: its oneOf or anyOf alternatives, or itself.
std::vector<const json*> alternatives(const json& schema) {
  std::vector<const json*> out;
  for (const char* key : {"oneOf", "anyOf"}) {
    if (auto list = schema.find(key); list != schema.end() && list->is_array()) {
      for (const json& alternative : *list) out.push_back(&alternative);
    }
  }
  if (out.empty()) out.push_back(&schema);
  return out;
}

bool is_index(const std::string& segment) {
  return !segment.empty() && segment.find_first_not_of("0123456789") == std::string::npos;
}

// The schema of `segment` under `schema` for a dotted key: a property of
// an object, an index into an array, or either of them in one of the
// field's alternatives (sheet.animation is one clip's object or a list of
// them: sheet.animation.clip and sheet.animation.0.clip both name a clip).
const json* segment_schema(const json& schema, const std::string& segment) {
  for (const json* alternative : alternatives(schema)) {
    if (const json* property = child_schema(*alternative, segment)) return property;
    if (const json* items = items_schema(*alternative); items && is_index(segment)) return items;
  }
  return nullptr;
}

// Command-line text as a value of a scalar schema type; nullopt when it is
// not one.
std::optional<json> scalar_from_text(const std::string& type, const std::string& raw) {
  if (type == "string") return json(raw);
  if (type == "boolean") {
    if (raw == "true" || raw == "1" || raw == "on") return json(true);
    if (raw == "false" || raw == "0" || raw == "off") return json(false);
    return std::nullopt;
  }
  if (type == "integer") {
    long long v = 0;
    const auto [ptr, ec] = std::from_chars(raw.data(), raw.data() + raw.size(), v);
    if (ec != std::errc() || ptr != raw.data() + raw.size()) return std::nullopt;
    return json(v);
  }
  if (type == "number") {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(raw.c_str(), &end);
    if (raw.empty() || end != raw.c_str() + raw.size() || errno == ERANGE) return std::nullopt;
    return json(v);
  }
  return std::nullopt;
}

std::vector<std::string> split_commas(const std::string& raw) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = raw.find(',', start);
    parts.push_back(raw.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

// Command-line text as a value of `schema`: a scalar type as itself; a list
// as JSON or as comma-separated items (outline.method=hull,edges,
// background=1,1,1); a field of alternatives as the first that takes it,
// JSON first where the text is JSON (clip=3 is an index, clip=walk a name);
// an object as JSON. nullopt when nothing takes it.
std::optional<json> value_from_text(const json& schema, const std::string& raw) {
  const json parsed = json::parse(raw, nullptr, false);
  const std::vector<const json*> choices = alternatives(schema);
  std::vector<const json*> lists;
  for (const json* alternative : choices) {
    if (alternative->value("type", "") == "array") lists.push_back(alternative);
  }
  // Commas make a list where the field takes one (outline.method=hull,edges).
  const bool list_text = !lists.empty() && raw.find(',') != std::string::npos;
  bool untyped = false;
  for (const json* alternative : choices) {
    const std::string type = alternative->value("type", "");
    if (type.empty()) untyped = true;
    if (type == "object") {
      if (parsed.is_object()) return parsed;
    } else if (type != "array" && !list_text) {
      // Text that reads as JSON of another alternative's type (3 for a clip
      // given by index) is taken as that type, not as a name.
      const bool json_of_other_type =
          type == "string" && choices.size() > 1 && !parsed.is_discarded() && !parsed.is_string();
      if (json_of_other_type) continue;
      if (const auto scalar = scalar_from_text(type, raw)) return scalar;
    }
  }
  for (const json* list : lists) {
    if (parsed.is_array()) return parsed;
    const json* items = items_schema(*list);
    json out = json::array();
    for (const std::string& part : split_commas(raw)) {
      const auto item = items ? value_from_text(*items, part) : std::optional<json>(json(part));
      if (!item) return std::nullopt;
      out.push_back(*item);
    }
    return out;
  }
  if (!parsed.is_discarded() && choices.size() > 1) return parsed;
  if (untyped) return parsed.is_discarded() ? json(raw) : parsed;
  return std::nullopt;
}

// What a field takes, for an error: "a number", "a string or a list".
std::string expected_text(const json& schema) {
  std::string out;
  for (const json* alternative : alternatives(schema)) {
    const std::string type = alternative->value("type", "");
    const std::string name = type == "array"     ? "a comma-separated list (or JSON array)"
                             : type == "object"  ? "JSON for an object"
                             : type == "integer" ? "an integer"
                             : type == "boolean" ? "true or false"
                                                 : "a " + type;
    if (!type.empty() && out.find(name) == std::string::npos) out += (out.empty() ? "" : " or ") + name;
  }
  return out.empty() ? "a value" : out;
}

// Unknown names are found by walking the schema itself, so the error can point
// at the unknown field rather than at the object that contains it.
void check_known_fields(const json& schema, const json& value, std::vector<std::string>& path) {
  if (value.is_object() && schema.contains("properties")) {
    for (const auto& [key, sub] : value.items()) {
      path.push_back(key);
      const json* child = child_schema(schema, key);
      if (!child && schema.value("additionalProperties", true) == false) {
        throw RequestError(400, "unknown_parameter", "unknown parameter '" + key + "'", json_pointer(path));
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

// The alternative of a validated value's field that describes it: the one
// of its kind (an object or a list: sheet.animation is either), or the
// field's own schema.
const json& schema_of_kind(const json& schema, const json& value) {
  for (const json* alternative : alternatives(schema)) {
    const auto type = alternative->find("type");
    if (type == alternative->end() || !type->is_string()) continue;
    if ((value.is_object() && *type == "object") || (value.is_array() && *type == "array")) return *alternative;
  }
  return schema;
}

// A field's default in `request`: the first of its x-default-when whose
// `present` pointer names a field the request has, else its `default`.
const json* default_of(const json& field_schema, const json& request) {
  if (auto when = field_schema.find("x-default-when"); when != field_schema.end()) {
    for (const json& rule : *when) {
      if (request.contains(json::json_pointer(rule.at("present").get<std::string>()))) return &rule.at("default");
    }
  }
  if (auto given = field_schema.find("default"); given != field_schema.end()) return &*given;
  return nullptr;
}

void fill_defaults(const json& field_schema, json& value, const json& request) {
  const json& schema = schema_of_kind(field_schema, value);
  if (value.is_object()) {
    if (auto props = schema.find("properties"); props != schema.end()) {
      for (const auto& [key, sub] : props->items()) {
        if (!value.contains(key)) {
          if (const json* fallback = default_of(sub, request)) value[key] = *fallback;
        }
        if (value.contains(key)) fill_defaults(sub, value[key], request);
      }
    }
  } else if (value.is_array()) {
    if (const json* items = items_schema(schema)) {
      for (auto& element : value) fill_defaults(*items, element, request);
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
  static const ParamSchema schema(json::parse(toond::proto_files::find("render-params.schema.json")));
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
  throw RequestError(400, "invalid_parameter", field + ": " + deepest.description + limits, json_pointer(segments));
}

nlohmann::json ParamSchema::validate_and_complete(const nlohmann::json& request) const {
  validate(request);
  json completed = request;
  fill_defaults(document_, completed, request);
  return completed;
}

void ParamSchema::set_from_text(nlohmann::json& params, std::string_view dotted, std::string_view text) const {
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
    const json* next = segment_schema(*schema, seg);
    if (!next) {
      throw RequestError(400, "unknown_parameter", "unknown parameter '" + key + "' (see GET /schema or proto/)",
                         json_pointer(segments));
    }
    schema = next;
    chain.push_back(schema);
  }

  const std::string raw(text);
  auto fail = [&](const std::string& why) {
    throw RequestError(400, "invalid_parameter", key + "=" + raw + ": " + why, json_pointer(segments));
  };
  const std::optional<json> converted = value_from_text(*schema, raw);
  if (!converted) fail("expected " + expected_text(*schema));
  const json& value = *converted;

  json* slot = &params;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& seg = segments[i];
    if (slot->is_array()) {
      if (!is_index(seg)) fail("'" + seg + "' names a field, but the value there is a list: give an index");
      std::size_t index = std::stoul(seg);
      if (index > slot->size()) fail("array index " + seg + " skips elements");
      if (index == slot->size()) slot->push_back(json::object());
      slot = &(*slot)[index];
    } else {
      bool next_is_index = i + 1 < segments.size() && is_index(segments[i + 1]);
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
