#include "render/vector/svg_document.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace toond::render::vector {
namespace {

// A coordinate with at most 2 decimals, trailing zeros dropped ("12.5",
// "3", never "-0").
void append_coordinate(std::string& out, double value) {
  const double rounded = std::round(value * 100.0) / 100.0;
  char buffer[64];
  const auto end =
      std::to_chars(buffer, buffer + sizeof buffer, rounded == 0 ? 0.0 : rounded, std::chars_format::fixed, 2).ptr;
  std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
  while (text.back() == '0') text.remove_suffix(1);
  if (text.back() == '.') text.remove_suffix(1);
  out += text;
}

// A number as it round-trips, for the camera's JSON.
void append_number(std::string& out, double value) {
  char buffer[64];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  out.append(buffer, end);
}

void append_matrix(std::string& out, const glm::dmat4& m) {
  out += '[';
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (c + r > 0) out += ',';
      append_number(out, m[c][r]);
    }
  }
  out += ']';
}

std::string hex_colour(const Srgb& c) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", c[0], c[1], c[2]);
  return buffer;
}

void open_layer(std::string& out, const char* id, const SvgDrawing& drawing, bool dashed) {
  out += "<g id=\"";
  out += id;
  out += "\" inkscape:groupmode=\"layer\" inkscape:label=\"";
  out += id;
  out += "\" fill=\"none\" stroke=\"" + hex_colour(drawing.colour) + "\" stroke-width=\"";
  append_number(out, drawing.stroke_px);
  out += "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
  if (dashed) {
    // Dashes and gaps in widths of the line, as a drafting pen's hidden lines.
    out += " stroke-dasharray=\"";
    append_number(out, 3 * drawing.stroke_px);
    out += ' ';
    append_number(out, 2 * drawing.stroke_px);
    out += '"';
  }
  out += ">\n";
}

// `stroke`: the path's own colour attribute, empty where it takes its layer's.
void append_paths(std::string& out, const std::vector<Polyline>& paths, const std::string& stroke) {
  for (const Polyline& line : paths) {
    const std::string d = path_data(line);
    if (d.empty()) continue;
    out += "<path d=\"" + d + "\"" + stroke + "/>\n";
  }
}

void append_layer(std::string& out, const char* id, const std::vector<ColouredStrokes>& sets,
                  const SvgDrawing& drawing) {
  open_layer(out, id, drawing, false);
  for (const ColouredStrokes& set : sets) {
    append_paths(out, set.strokes, set.colour == drawing.colour ? "" : " stroke=\"" + hex_colour(set.colour) + "\"");
  }
  out += "</g>\n";
}

void append_hidden_layer(std::string& out, const std::vector<Polyline>& paths, const SvgDrawing& drawing) {
  open_layer(out, "hidden", drawing, true);
  append_paths(out, paths, "");
  out += "</g>\n";
}

}  // namespace

std::string path_data(const Polyline& line) {
  std::string d;
  long long last_x = 0, last_y = 0;
  std::size_t kept = 0;
  for (const glm::dvec2& p : line.points) {
    const long long x = std::llround(p.x * 100.0), y = std::llround(p.y * 100.0);
    if (kept > 0 && x == last_x && y == last_y) continue;
    d += kept == 0 ? "M" : kept == 1 ? "L" : " ";
    append_coordinate(d, p.x);
    d += ',';
    append_coordinate(d, p.y);
    last_x = x;
    last_y = y;
    ++kept;
  }
  if (kept < 2) return {};
  if (line.closed && kept > 2) d += 'Z';
  return d;
}

std::string camera_json(const SvgDrawing& drawing) {
  std::string out = "{\"view\":";
  append_matrix(out, drawing.view);
  out += ",\"projection\":";
  append_matrix(out, drawing.projection);
  out += ",\"width\":" + std::to_string(drawing.width) + ",\"height\":" + std::to_string(drawing.height) + "}";
  return out;
}

std::string write_svg(const SvgDrawing& drawing) {
  const std::string w = std::to_string(drawing.width), h = std::to_string(drawing.height);
  std::string out =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" "
      "version=\"1.1\" width=\"" +
      w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  out += "<metadata id=\"toond-camera\">" + camera_json(drawing) + "</metadata>\n";
  if (drawing.hidden) append_hidden_layer(out, *drawing.hidden, drawing);
  for (LineKind kind : kAllLineKinds) {
    append_layer(out, layer_id(kind), drawing.layers[static_cast<std::size_t>(kind)], drawing);
  }
  out += "</svg>\n";
  return out;
}

}  // namespace toond::render::vector
