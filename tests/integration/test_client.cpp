#include "test_client.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "image/png_codec.h"
#include "support/shared_models.h"

namespace toond::test {

httplib::Result upload_files(httplib::Client& client, const std::filesystem::path& folder,
                             const std::vector<std::string>& files) {
  httplib::MultipartFormDataItems items;
  for (const auto& f : files) {
    items.push_back({"file", read_file(folder / f), f, "application/octet-stream"});
  }
  return client.Post("/models", items);
}

httplib::Result upload_model_folder(httplib::Client& client, const std::filesystem::path& folder) {
  static const std::vector<std::string> wanted = {".obj", ".mtl", ".png", ".jpg", ".jpeg", ".tga", ".bmp"};
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (std::find(wanted.begin(), wanted.end(), ext) == wanted.end()) continue;
    files.push_back(std::filesystem::relative(entry.path(), folder).generic_string());
  }
  std::sort(files.begin(), files.end());
  return upload_files(client, folder, files);
}

std::string upload_obj_text(httplib::Client& client, const std::string& obj, const std::string& name) {
  httplib::MultipartFormDataItems items = {{"file", obj, name, "text/plain"}};
  auto res = client.Post("/models", items);
  if (!res || (res->status != 200 && res->status != 201)) {
    ADD_FAILURE() << "upload of " << name << " failed: " << (res ? res->body : httplib::to_string(res.error()));
    return {};
  }
  return nlohmann::json::parse(res->body)["id"];
}

httplib::Result post_json(httplib::Client& client, const std::string& path, const nlohmann::json& body) {
  return client.Post(path.c_str(), body.dump(), "application/json");
}

image::Image render_ok(httplib::Client& client, const nlohmann::json& params) {
  auto res = post_json(client, "/render", params);
  if (!res) {
    ADD_FAILURE() << "no answer from /render: " << httplib::to_string(res.error());
    return {};
  }
  if (res->status != 200) {
    ADD_FAILURE() << "/render answered " << res->status << ": " << res->body;
    return {};
  }
  EXPECT_EQ(res->get_header_value("Content-Type"), "image/png");
  return image::decode_png(res->body);
}

nlohmann::json error_of(const httplib::Result& res) {
  if (!res) return nlohmann::json::object();
  auto body = nlohmann::json::parse(res->body, nullptr, false);
  if (body.is_discarded() || !body.contains("error")) {
    ADD_FAILURE() << "error answer is not the JSON error shape: " << res->body;
    return nlohmann::json::object();
  }
  return body["error"];
}

image::Image tile_of(const image::Image& sheet, const nlohmann::json& rect) {
  image::Image tile;
  tile.width = rect["w"];
  tile.height = rect["h"];
  tile.rgba.resize(static_cast<std::size_t>(tile.width) * tile.height * 4);
  for (int y = 0; y < tile.height; ++y) {
    std::copy_n(sheet.pixel(rect["x"].get<int>(), rect["y"].get<int>() + y), tile.width * 4, tile.pixel(0, y));
  }
  return tile;
}

std::optional<std::string> png_text(const std::string& png, const std::string& key) {
  auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(png[at + i]);
    return v;
  };
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t length = be32(at);
    const std::string type = png.substr(at + 4, 4);
    if (at + 12 + length > png.size()) break;
    const std::string data = png.substr(at + 8, length);
    if (type == "tEXt") {
      const std::size_t nul = data.find('\0');
      if (nul != std::string::npos && data.substr(0, nul) == key) return data.substr(nul + 1);
    }
    if (type == "IEND") break;
    at += 12 + length;
  }
  return std::nullopt;
}

}  // namespace toond::test
