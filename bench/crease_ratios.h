#pragma once
// What crease lines cost the default frame: the demo model's, each
// hard-edged shared model's and Minetest's player's (at rest and posed)
// default request at 512² (crease lines drawn along its crease edges and
// the seams where its parts cross, or found in screen space) against the
// same request with `creases: never`, interleaved, as medians of server
// time and their ratio (issue 47 asks for at most 1.25 on the windmill, on
// llvmpipe).
#include <filesystem>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace toond::bench {

nlohmann::json run_crease_ratios(httplib::Client& client, const std::filesystem::path& models, int repeats);

}  // namespace toond::bench
