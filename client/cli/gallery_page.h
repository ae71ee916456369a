#pragma once
// index.html of `toon gallery`: plain HTML and CSS, no script. One section
// per model; each render with its look's name and description, the exact
// JSON it was rendered with, and the `toon render` command that repeats it.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace toond::cli::gallery {

struct PageRender {
  std::string look;
  std::string description;
  std::string image;  // path relative to index.html ("spot/bw_comic.png"); empty when it failed
  nlohmann::json params;
  std::string command;
  std::string error;  // why it failed; empty on success
};

struct PageModel {
  std::string name;
  std::string obj_path;
  std::string error;  // the upload failed (the renders say so too)
  std::vector<PageRender> renders;
};

struct PageInfo {
  std::string title = "toond gallery";
  std::string contact_sheet;  // relative path, empty when none was written
  std::string server;
  std::string renderer;  // GL renderer from /healthz, may be empty
  int size = 0;
};

// Text with & < > " ' replaced by entities, for element content and
// attribute values alike.
std::string html_escape(std::string_view text);

// A relative path for an href or src: every byte but letters, digits,
// - _ . ~ and / percent-encoded.
std::string url_path(std::string_view path);

// JSON for people: two-space indents, but an object or array whose one-line
// form fits in `width` columns stays on one line ("direction": [0, -1, 0]).
std::string pretty_json(const nlohmann::json& value, std::size_t width = 78);

std::string gallery_page(const PageInfo& info, const std::vector<PageModel>& models);

}  // namespace toond::cli::gallery
