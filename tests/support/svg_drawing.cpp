#include "support/svg_drawing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <stdexcept>

namespace toond::test {
namespace {

std::map<std::string, std::string> attributes_of(const std::string& tag) {
  static const std::regex attribute(R"re(([\w:-]+)="([^"]*)")re");
  std::map<std::string, std::string> out;
  for (auto it = std::sregex_iterator(tag.begin(), tag.end(), attribute); it != std::sregex_iterator(); ++it) {
    out[(*it)[1]] = (*it)[2];
  }
  return out;
}

// M, L and Z with numbers between, separated by commas or spaces.
SvgStroke stroke_of(const std::string& d) {
  SvgStroke stroke;
  std::size_t i = 0;
  std::vector<double> numbers;
  const auto flush = [&] {
    if (numbers.size() % 2 != 0) throw std::runtime_error("odd number of coordinates in " + d);
    for (std::size_t k = 0; k < numbers.size(); k += 2) stroke.points.push_back({numbers[k], numbers[k + 1]});
    numbers.clear();
  };
  while (i < d.size()) {
    const char c = d[i];
    if (c == 'M' || c == 'L') {
      if (c == 'M' && !stroke.points.empty()) throw std::runtime_error("more than one M in a path: " + d);
      flush();
      ++i;
    } else if (c == 'Z') {
      flush();
      stroke.closed = true;
      ++i;
    } else if (c == ',' || c == ' ') {
      ++i;
    } else {
      std::size_t used = 0;
      numbers.push_back(std::stod(d.substr(i), &used));
      i += used;
    }
  }
  flush();
  return stroke;
}

}  // namespace

SvgFile read_svg_drawing(const std::string& text) {
  SvgFile file;
  const std::size_t svg_at = text.find("<svg");
  if (svg_at == std::string::npos) throw std::runtime_error("no <svg> element");
  const auto svg = attributes_of(text.substr(svg_at, text.find('>', svg_at) - svg_at));
  file.width = std::stoi(svg.at("width"));
  file.height = std::stoi(svg.at("height"));
  const std::size_t meta = text.find("<metadata id=\"toond-camera\">");
  if (meta == std::string::npos) throw std::runtime_error("no toond-camera metadata");
  const std::size_t json_at = text.find('>', meta) + 1;
  file.camera = nlohmann::json::parse(text.substr(json_at, text.find("</metadata>", json_at) - json_at));
  for (std::size_t g = text.find("<g "); g != std::string::npos; g = text.find("<g ", g + 1)) {
    const std::size_t open_end = text.find('>', g);
    const std::size_t close = text.find("</g>", open_end);
    SvgLayer layer;
    layer.attributes = attributes_of(text.substr(g, open_end - g));
    const std::string body = text.substr(open_end, close - open_end);
    for (std::size_t p = body.find("<path "); p != std::string::npos; p = body.find("<path ", p + 1)) {
      const auto path = attributes_of(body.substr(p, body.find("/>", p) - p));
      const std::string& d = path.at("d");
      file.path_data.push_back(d);
      SvgStroke& stroke = layer.strokes.emplace_back(stroke_of(d));
      stroke.colour = path.count("stroke") ? path.at("stroke") : layer.attributes["stroke"];
    }
    file.layers[layer.attributes.at("id")] = std::move(layer);
  }
  return file;
}

glm::dvec2 project_with(const nlohmann::json& camera, const glm::dvec3& point) {
  glm::dmat4 view(1.0), projection(1.0);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      view[c][r] = camera["view"][4 * c + r].get<double>();
      projection[c][r] = camera["projection"][4 * c + r].get<double>();
    }
  }
  const glm::dvec4 clip = projection * view * glm::dvec4(point, 1.0);
  const double w = camera["width"].get<double>(), h = camera["height"].get<double>();
  return {(clip.x / clip.w * 0.5 + 0.5) * w, (0.5 - clip.y / clip.w * 0.5) * h};
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

std::vector<std::pair<glm::dvec2, glm::dvec2>> segments_of(const std::vector<SvgStroke>& strokes) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> out;
  for (const SvgStroke& s : strokes) {
    for (std::size_t i = 1; i < s.points.size(); ++i) out.emplace_back(s.points[i - 1], s.points[i]);
    if (s.closed && s.points.size() > 2) out.emplace_back(s.points.back(), s.points.front());
  }
  return out;
}

double distance_to(const std::vector<std::pair<glm::dvec2, glm::dvec2>>& segments, glm::dvec2 p) {
  double best = std::numeric_limits<double>::max();
  for (const auto& [a, b] : segments) best = std::min(best, distance_to_segment(p, a, b));
  return best;
}

}  // namespace toond::test
