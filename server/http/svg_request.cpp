#include "http/svg_request.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>

#include "request_error.h"

namespace toond::http {
namespace {

// The media types an Accept header lists, lower case, parameters dropped
// and those of q=0 (refused) left out.
std::vector<std::string> accepted_types(const std::string& accept) {
  std::vector<std::string> types;
  std::stringstream items(accept);
  for (std::string item; std::getline(items, item, ',');) {
    std::string lower;
    for (char c : item) {
      if (!std::isspace(static_cast<unsigned char>(c)))
        lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    const std::size_t semicolon = lower.find(';');
    const std::size_t q = lower.find(";q=", semicolon == std::string::npos ? lower.size() : semicolon);
    const bool refused = q != std::string::npos && std::strtod(lower.c_str() + q + 3, nullptr) <= 0.0;
    const std::string type = lower.substr(0, semicolon);
    if (!refused) types.push_back(type);
  }
  return types;
}

bool lists(const std::vector<std::string>& types, const std::string& type) {
  return std::find(types.begin(), types.end(), type) != types.end();
}

}  // namespace

void apply_svg_accept(const std::string& accept, nlohmann::json& request) {
  if (!request.is_object() || request.contains("output")) return;
  const std::vector<std::string> types = accepted_types(accept);
  if (lists(types, "image/svg+xml") && !lists(types, "image/png")) request["output"] = "svg";
}

void check_svg_fields(const nlohmann::json& sent, const nlohmann::json& completed) {
  const bool svg = completed.value("output", "") == "svg";
  if (!svg && sent.is_object() && sent.contains("svg")) {
    const nlohmann::json& block = sent["svg"];
    const std::string path = block.is_object() && !block.empty() ? "/svg/" + block.begin().key() : "/svg";
    throw RequestError(
        400, "invalid_parameter",
        path + ": applies to output svg alone; this request's output is " + completed.value("output", "color"), path);
  }
  if (svg && completed.contains("sheet")) {
    throw RequestError(400, "invalid_parameter", "/sheet: output svg draws one image, not a sheet", "/sheet");
  }
}

}  // namespace toond::http
