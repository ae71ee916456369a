#pragma once
// What a render request says about the vector answer (output svg) besides
// its parameters: an Accept header that asks for SVG, and the `svg` block's
// fields, which mean nothing to any other output.
#include <string>

#include <nlohmann/json.hpp>

namespace toond::http {

// A request that names no `output` and whose Accept header asks for
// image/svg+xml (and not image/png) gets `output: "svg"`.
void apply_svg_accept(const std::string& accept, nlohmann::json& request);

// Throws RequestError 400 naming the field: an `svg` field (`sent`: the
// request as the client sent it) when the output (`completed`: over its
// preset and the defaults) is not svg; a `sheet` with output svg, which
// draws one image.
void check_svg_fields(const nlohmann::json& sent, const nlohmann::json& completed);

}  // namespace toond::http
