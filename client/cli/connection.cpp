#include "connection.h"

#include <cstdint>
#include <iostream>

#include "reply.h"

namespace toond::cli {

Connection::Connection(const std::string& server)
    : server_(server), url_(parse_server_url(server)), client_(url_.scheme_host_port) {
  client_.set_connection_timeout(kConnectTimeoutS, 0);
  client_.set_read_timeout(kReadTimeoutS, 0);
  client_.set_write_timeout(kReadTimeoutS, 0);
  client_.set_default_headers({{"User-Agent", std::string("toon/") + TOOND_VERSION}});
}

httplib::Result Connection::get(const std::string& path) { return client_.Get(url_.base_path + path); }

httplib::Result Connection::post_json(const std::string& path, const nlohmann::json& body) {
  return client_.Post(url_.base_path + path, body.dump(), "application/json");
}

httplib::Result Connection::post_multipart(const std::string& path, const httplib::MultipartFormDataItems& items) {
  return client_.Post(url_.base_path + path, items);
}

std::string Connection::describe_failure(const httplib::Result& result) const {
  const httplib::Error e = result.error();
  switch (e) {
    case httplib::Error::Connection:
      return "cannot reach toond at " + server_ + " (connection failed; is the daemon running?)";
    case httplib::Error::ConnectionTimeout:
      return "cannot reach toond at " + server_ + " (no connection within " + std::to_string(kConnectTimeoutS) + " s)";
    case httplib::Error::Read:
      return "no answer from toond at " + server_ + " (connection closed, or nothing within " +
             std::to_string(kReadTimeoutS) + " s)";
    case httplib::Error::Write:
      return "cannot reach toond at " + server_ + " (the connection broke while sending)";
    default:
      break;
  }
  return "cannot reach toond at " + server_ + " (" + httplib::to_string(e) + ")";
}

int Connection::network_failure(const httplib::Result& result) const {
  std::cerr << "toon: " << describe_failure(result) << "\n";
  return 1;
}

int error_reply(const httplib::Response& response) {
  std::cerr << "toon: "
            << describe_error_reply(response.status, response.body, response.get_header_value("Retry-After")) << "\n";
  return 1;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::cerr << "toon: warning: " << w << "\n";
}

httplib::MultipartFormDataItems bundle_parts(const BundleScan& scan) {
  httplib::MultipartFormDataItems items;
  for (const BundleFile& f : scan.files) {
    items.push_back({"file", f.content, f.name, content_type_for(f.name)});
  }
  return items;
}

std::string bundle_summary(const BundleScan& scan) {
  std::uint64_t bytes = 0;
  std::string names;
  for (const BundleFile& f : scan.files) {
    bytes += f.content.size();
    names += " " + f.name;
  }
  return std::to_string(scan.files.size()) + (scan.files.size() == 1 ? " file" : " files") + " (" + human_bytes(bytes) +
         "):" + names;
}

}  // namespace toond::cli
