#include "gallery_page.h"

#include <cctype>
#include <cstdio>

namespace toond::cli::gallery {
namespace {

constexpr std::string_view kStyle = R"(
:root { color-scheme: light dark; --bg: #f4f4f6; --card: #ffffff; --ink: #1d1d22; --muted: #6b6b76; --line: #d9d9df; }
@media (prefers-color-scheme: dark) {
  :root { --bg: #18181c; --card: #222228; --ink: #e8e8ee; --muted: #9a9aa6; --line: #36363e; }
}
* { box-sizing: border-box; }
body { margin: 0; padding: 1.5rem 2rem 4rem; background: var(--bg); color: var(--ink);
       font: 15px/1.45 system-ui, -apple-system, "Segoe UI", sans-serif; }
h1 { margin: 0 0 .25rem; font-size: 1.6rem; }
h2 { margin: 2.5rem 0 .25rem; font-size: 1.3rem; border-bottom: 1px solid var(--line); padding-bottom: .3rem; }
.meta, .obj { color: var(--muted); margin: 0 0 1rem; }
nav a { margin-right: 1rem; }
a { color: inherit; }
.sheet img { max-width: 100%; height: auto; border: 1px solid var(--line); }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(260px, 1fr)); gap: 1rem; }
figure { margin: 0; padding: .6rem; background: var(--card); border: 1px solid var(--line); border-radius: 6px; }
figure img { display: block; width: 100%; height: auto; aspect-ratio: 1; object-fit: contain; }
figcaption { margin-top: .4rem; }
figcaption b { font-family: ui-monospace, SFMono-Regular, Menlo, monospace; }
.kind { color: var(--muted); font-size: .8em; margin-left: .4em; }
.desc { display: block; color: var(--muted); font-size: .9em; }
details { margin-top: .4rem; font-size: .85em; }
summary { cursor: pointer; color: var(--muted); }
pre, code { font-family: ui-monospace, SFMono-Regular, Menlo, monospace; font-size: .85em; }
pre { margin: .3rem 0; padding: .5rem; overflow-x: auto; background: var(--bg); border-radius: 4px;
      white-space: pre-wrap; word-break: break-all; }
.failed { display: flex; align-items: center; justify-content: center; aspect-ratio: 1; padding: 1rem;
          background: #9b2128; color: #fff; font-size: .9em; word-break: break-word; }
)";

std::string one_line(const nlohmann::json& v) {
  if (v.is_object()) {
    std::string out = "{";
    bool first = true;
    for (const auto& [key, child] : v.items()) {
      out += (first ? "" : ", ") + nlohmann::json(key).dump() + ": " + one_line(child);
      first = false;
    }
    return out + "}";
  }
  if (v.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + one_line(v[i]);
    return out + "]";
  }
  return v.dump();
}

void pretty_into(std::string& out, const nlohmann::json& v, std::size_t indent, std::size_t lead, std::size_t width) {
  const std::string flat = one_line(v);
  if (!(v.is_object() || v.is_array()) || v.empty() || lead + flat.size() <= width) {
    out += flat;
    return;
  }
  const std::string pad(indent + 2, ' ');
  out += v.is_object() ? "{\n" : "[\n";
  std::size_t i = 0;
  for (const auto& [key, child] : v.items()) {
    out += pad;
    std::size_t child_lead = pad.size();
    if (v.is_object()) {
      const std::string k = nlohmann::json(key).dump() + ": ";
      out += k;
      child_lead += k.size();
    }
    pretty_into(out, child, indent + 2, child_lead, width);
    out += ++i < v.size() ? ",\n" : "\n";
  }
  out += std::string(indent, ' ') + (v.is_object() ? "}" : "]");
}

void append_render(std::string& out, const std::string& model, const PageRender& r) {
  out += "<figure id=\"" + html_escape(url_path(model + "--" + r.look)) + "\">\n";
  if (r.error.empty() && !r.image.empty()) {
    out += "<a href=\"" + html_escape(url_path(r.image)) + "\"><img src=\"" + html_escape(url_path(r.image)) +
           "\" alt=\"" + html_escape(r.look) + "\" loading=\"lazy\"></a>\n";
  } else {
    out += "<div class=\"failed\">failed: " + html_escape(r.error) + "</div>\n";
  }
  out += "<figcaption><b>" + html_escape(r.look) + "</b>";
  if (r.params.is_object() && r.params.contains("preset")) out += "<span class=\"kind\">preset</span>";
  if (!r.description.empty()) out += "<span class=\"desc\">" + html_escape(r.description) + "</span>";
  out += "</figcaption>\n";
  out += "<details><summary>parameters</summary><pre>" + html_escape(pretty_json(r.params)) + "</pre></details>\n";
  if (!r.command.empty()) {
    out += "<details><summary>toon render</summary><pre>" + html_escape(r.command) + "</pre></details>\n";
  }
  out += "</figure>\n";
}

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
        break;
    }
  }
  return out;
}

std::string url_path(std::string_view path) {
  std::string out;
  for (char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') {
      out += c;
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", u);
      out += buf;
    }
  }
  return out;
}

std::string pretty_json(const nlohmann::json& value, std::size_t width) {
  std::string out;
  pretty_into(out, value, 0, 0, width);
  return out;
}

std::string gallery_page(const PageInfo& info, const std::vector<PageModel>& models) {
  std::string out;
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out +=
      "<title>" + html_escape(info.title) + "</title>\n<style>" + std::string(kStyle) + "</style>\n</head>\n<body>\n";
  out += "<h1>" + html_escape(info.title) + "</h1>\n<p class=\"meta\">";
  std::size_t renders = 0, failed = 0;
  for (const PageModel& m : models) {
    renders += m.renders.size();
    for (const PageRender& r : m.renders) failed += r.error.empty() ? 0 : 1;
  }
  out += std::to_string(renders) + " renders of " + std::to_string(models.size()) +
         (models.size() == 1 ? " model" : " models");
  if (info.size > 0) out += " at " + std::to_string(info.size) + "×" + std::to_string(info.size);
  if (!info.server.empty()) out += " by " + html_escape(info.server);
  if (!info.renderer.empty()) out += " (" + html_escape(info.renderer) + ")";
  if (failed) out += "; <strong>" + std::to_string(failed) + " failed</strong>";
  out += ". Click an image for full size; each keeps the parameters that made it.</p>\n";

  out += "<nav>";
  for (const PageModel& m : models) {
    out += "<a href=\"#" + html_escape(url_path(m.name)) + "\">" + html_escape(m.name) + "</a>";
  }
  out += "</nav>\n";

  if (!info.contact_sheet.empty()) {
    out +=
        "<h2>Contact sheet</h2>\n<p class=\"meta\">Rows are models, columns are looks, in the "
        "order below.</p>\n<p class=\"sheet\"><a href=\"" +
        html_escape(url_path(info.contact_sheet)) + "\"><img src=\"" + html_escape(url_path(info.contact_sheet)) +
        "\" alt=\"contact sheet\"></a></p>\n";
  }

  for (const PageModel& m : models) {
    out += "<section id=\"" + html_escape(url_path(m.name)) + "\">\n<h2>" + html_escape(m.name) + "</h2>\n";
    out += "<p class=\"obj\"><code>" + html_escape(m.obj_path) + "</code>";
    if (!m.error.empty()) out += " — <strong>" + html_escape(m.error) + "</strong>";
    out += "</p>\n<div class=\"grid\">\n";
    for (const PageRender& r : m.renders) append_render(out, m.name, r);
    out += "</div>\n</section>\n";
  }
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace toond::cli::gallery
