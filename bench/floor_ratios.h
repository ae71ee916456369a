#pragma once
// How far the default frame is from its geometry floor, in one run: the
// default request (no lod, no msaa) for the bunny and spot at 512² against
// the same request drawn in one flat colour with every effect and line off,
// and beside them the default without its outline and without outline and
// specular (the least any way of drawing those could cost), all
// interleaved; the PNG encode's Server-Timing at 512² and 1024²;
// and throughput with frames in flight (a second daemon started with
// --frames-in-flight 2) against the first, 1 and 16 clients, interleaved.
#include <filesystem>
#include <string>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace toond::bench {

// The request with one constant colour and nothing else (no lights, bands,
// outline or effects), read back and encoded as usual: what drawing the
// same mesh at the same size, samples and detail costs at the least.
nlohmann::json geometry_floor_request(nlohmann::json params);

nlohmann::json run_floor_ratios(httplib::Client& client, const std::string& url,
                                const std::vector<std::string>& daemon_args, const std::filesystem::path& models,
                                int repeats, double load_seconds);

}  // namespace toond::bench
