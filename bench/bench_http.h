#pragma once
// Timing one render over HTTP: wall time from request to decoded answer on
// the client, the server's own figures from Server-Timing, the PNG, and the
// level of detail the server reports.
#include <filesystem>
#include <string>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "image/image.h"

namespace toond::bench {

struct TimedRender {
  double wall_ms = 0;    // request sent → PNG bytes received (client side)
  double server_ms = 0;  // every Server-Timing entry but the queue wait
  double png_ms = 0;     // the encode alone
  double queue_ms = 0;
  std::size_t png_bytes = 0;
  std::string lod;  // X-Toond-Lod
  std::string png;  // the answer, still encoded
};

// POSTs /render and times it; throws std::runtime_error on anything but 200.
// Each request asks the server not to answer from a result cache.
TimedRender render_timed(httplib::Client& client, const nlohmann::json& params);

// Sum of the `dur` values of a Server-Timing header, without `queue`; the
// queue wait and the PNG encode come back apart through the pointers.
double server_time_ms(const std::string& header, double* queue_ms, double* png_ms);

// Uploads the model and image files of a folder; returns the model id.
std::string upload_folder(httplib::Client& client, const std::filesystem::path& folder);
// Uploads OBJ text as a one-file bundle; returns the model id.
std::string upload_obj(httplib::Client& client, const std::string& obj, const std::string& name);

}  // namespace toond::bench
