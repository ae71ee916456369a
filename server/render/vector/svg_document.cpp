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

// The text being written: handed on a piece at a time where a sender is
// given, else kept whole.
class SvgText {
 public:
  SvgText(const SvgSend* send, std::size_t piece_bytes) : send_(send), piece_bytes_(piece_bytes) {}
  std::string& text() { return text_; }
  // Between two elements: the piece handed on once it is large enough.
  // False once the receiver has gone; nothing more need be written.
  bool settle() { return send_ == nullptr || text_.size() < piece_bytes_ || hand_on(); }
  bool finish() { return send_ == nullptr || text_.empty() || hand_on(); }

 private:
  bool hand_on() {
    const bool taken = (*send_)(text_);
    text_.clear();
    return taken;
  }
  const SvgSend* send_;
  std::size_t piece_bytes_;
  std::string text_;
};

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
bool append_paths(SvgText& out, const std::vector<Polyline>& paths, const std::string& stroke) {
  for (const Polyline& line : paths) {
    const std::string d = path_data(line);
    if (d.empty()) continue;
    out.text() += "<path d=\"" + d + "\"" + stroke + "/>\n";
    if (!out.settle()) return false;
  }
  return true;
}

bool append_layer(SvgText& out, const char* id, const std::vector<ColouredStrokes>& sets, const SvgDrawing& drawing) {
  open_layer(out.text(), id, drawing, false);
  for (const ColouredStrokes& set : sets) {
    const std::string stroke = set.colour == drawing.colour ? "" : " stroke=\"" + hex_colour(set.colour) + "\"";
    if (!append_paths(out, set.strokes, stroke)) return false;
  }
  out.text() += "</g>\n";
  return true;
}

bool append_hidden_layer(SvgText& out, const std::vector<Polyline>& paths, const SvgDrawing& drawing) {
  open_layer(out.text(), "hidden", drawing, true);
  if (!append_paths(out, paths, "")) return false;
  out.text() += "</g>\n";
  return true;
}

// The whole document into `out`; false where its receiver went away.
bool write_document(const SvgDrawing& drawing, SvgText& out) {
  const std::string w = std::to_string(drawing.width), h = std::to_string(drawing.height);
  out.text() +=
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" "
      "version=\"1.1\" width=\"" +
      w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  out.text() += "<metadata id=\"toond-camera\">" + camera_json(drawing) + "</metadata>\n";
  if (drawing.hidden && !append_hidden_layer(out, *drawing.hidden, drawing)) return false;
  for (LineKind kind : kAllLineKinds) {
    if (!append_layer(out, layer_id(kind), drawing.layers[static_cast<std::size_t>(kind)], drawing)) return false;
  }
  out.text() += "</svg>\n";
  return out.finish();
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
  SvgText out(nullptr, 0);
  write_document(drawing, out);
  return std::move(out.text());
}

bool write_svg(const SvgDrawing& drawing, const SvgSend& send, std::size_t piece_bytes) {
  SvgText out(&send, piece_bytes);
  return write_document(drawing, out);
}

std::size_t estimated_svg_bytes(const SvgDrawing& drawing) {
  // A point: two coordinates of up to 7 characters and a separator; a
  // path: its element around them, with a colour of its own.
  constexpr std::size_t kPointBytes = 16, kPathBytes = 48, kFrameBytes = 2048;
  std::size_t bytes = kFrameBytes;
  const auto add = [&](const std::vector<Polyline>& paths) {
    for (const Polyline& line : paths) bytes += kPathBytes + kPointBytes * line.points.size();
  };
  for (const std::vector<ColouredStrokes>& layer : drawing.layers) {
    for (const ColouredStrokes& set : layer) add(set.strokes);
  }
  if (drawing.hidden) add(*drawing.hidden);
  return bytes;
}

}  // namespace toond::render::vector
