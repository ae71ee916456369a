#pragma once
// toond's half of the side-by-side with three.js (bench/threejs/): the
// Stanford bunny at 512², 3 bands, hull outline, no specular, without AA
// and with MSAA 4, auto LOD and full detail, warm request-to-PNG over HTTP;
// the image error of auto against full; and the floor: clearing, reading
// back and PNG-encoding an image of the same size and content in this
// process, on the same GL driver.
#include <filesystem>
#include <string>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace toond::bench {

nlohmann::json run_versus(httplib::Client& client, const std::string& url, const std::filesystem::path& models,
                          int repeats, double load_seconds);

}  // namespace toond::bench
