#pragma once
// The render-parameter schema (proto/render-params.schema.json) as the one
// source of truth: the server validates requests with it, fills defaults
// from it, and the CLI checks `--set key.sub=value` against it. No list of
// fields exists anywhere else.
#include <memory>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "request_error.h"

namespace toond::proto {

class ParamSchema {
 public:
  // The schema embedded at build time.
  static const ParamSchema& render_params();

  explicit ParamSchema(const nlohmann::json& document);
  ~ParamSchema();
  ParamSchema(const ParamSchema&) = delete;
  ParamSchema& operator=(const ParamSchema&) = delete;

  const nlohmann::json& document() const { return document_; }

  // Checks a request against the schema and returns it with every absent
  // field set to its default. Throws RequestError (400) whose path points at
  // the offending field: code "unknown_parameter" for a name the schema does
  // not have, "invalid_parameter" for a wrong type, range or enum value.
  nlohmann::json validate_and_complete(const nlohmann::json& request) const;

  // Same checks, no defaults added.
  void validate(const nlohmann::json& request) const;

  // Sets `dotted` ("outline.width", "lights.0.color", "background",
  // "sheet.animation.clip") in `params` from command-line text. The key
  // walks the schema's objects and arrays, and the alternatives of a field
  // that may be either (oneOf/anyOf: sheet.animation is a clip's object or a
  // list of them). The text is converted to the type the schema gives that
  // field: number, integer, boolean, string; a list as comma-separated
  // items or JSON; an object as JSON; among alternatives, the first that
  // takes it (JSON first: animation.clip=3 is an index). Throws RequestError
  // naming the key when the schema has no such field or the text does not
  // fit its type.
  void set_from_text(nlohmann::json& params, std::string_view dotted, std::string_view text) const;

 private:
  nlohmann::json document_;
  struct Compiled;
  std::unique_ptr<Compiled> compiled_;
};

// "/a/b/0" from {"a","b","0"}, escaping ~ and / as RFC 6901 says.
std::string json_pointer(const std::vector<std::string>& segments);

}  // namespace toond::proto
