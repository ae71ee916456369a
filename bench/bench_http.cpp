#include "bench_http.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace toond::bench {
namespace {

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string upload(httplib::Client& client, const httplib::MultipartFormDataItems& items) {
  auto res = client.Post("/models", items);
  if (!res || (res->status != 200 && res->status != 201)) {
    throw std::runtime_error("upload failed: " +
                             (res ? std::to_string(res->status) + " " + res->body : httplib::to_string(res.error())));
  }
  return nlohmann::json::parse(res->body).at("id").get<std::string>();
}

}  // namespace

double server_time_ms(const std::string& header, double* queue_ms, double* png_ms) {
  double total = 0;
  double reported_total = -1;
  std::stringstream entries(header);
  std::string entry;
  while (std::getline(entries, entry, ',')) {
    const auto name_start = entry.find_first_not_of(' ');
    if (name_start == std::string::npos) continue;
    const std::string name = entry.substr(name_start, entry.find(';', name_start) - name_start);
    const auto dur = entry.find("dur=");
    if (dur == std::string::npos) continue;
    const double ms = std::stod(entry.substr(dur + 4));
    if (name == "queue") {
      if (queue_ms) *queue_ms = ms;
      continue;
    }
    if (name == "total") {
      reported_total = ms;
      continue;
    }
    if (name == "png" && png_ms) *png_ms = ms;
    total += ms;
  }
  // GPU-timed passes can overlap the render thread's time, so their sum can
  // exceed the work's wall-clock time: the server's own total is preferred.
  return reported_total >= 0 ? reported_total : total;
}

TimedRender render_timed(httplib::Client& client, const nlohmann::json& params) {
  const std::string body = params.dump();
  const httplib::Headers headers = {{"Cache-Control", "no-cache"}};
  const auto start = std::chrono::steady_clock::now();
  auto res = client.Post("/render", headers, body, "application/json");
  const auto end = std::chrono::steady_clock::now();
  if (!res) throw std::runtime_error("render: no answer (" + httplib::to_string(res.error()) + ")");
  if (res->status != 200) throw std::runtime_error("render: " + std::to_string(res->status) + " " + res->body);
  TimedRender t;
  t.wall_ms = std::chrono::duration<double, std::milli>(end - start).count();
  t.server_ms = server_time_ms(res->get_header_value("Server-Timing"), &t.queue_ms, &t.png_ms);
  t.lod = res->get_header_value("X-Toond-Lod");
  t.png_bytes = res->body.size();
  t.png = std::move(res->body);
  return t;
}

std::string upload_folder(httplib::Client& client, const std::filesystem::path& folder) {
  static const std::vector<std::string> wanted = {".obj", ".mtl", ".png", ".jpg", ".jpeg", ".tga", ".bmp"};
  httplib::MultipartFormDataItems items;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (std::find(wanted.begin(), wanted.end(), ext) == wanted.end()) continue;
    const std::string name = std::filesystem::relative(entry.path(), folder).generic_string();
    items.push_back({name, read_all(entry.path()), name, "application/octet-stream"});
  }
  return upload(client, items);
}

std::string upload_obj(httplib::Client& client, const std::string& obj, const std::string& name) {
  return upload(client, {{name, obj, name, "text/plain"}});
}

}  // namespace toond::bench
