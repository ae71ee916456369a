#pragma once
// Reading back the SVG line drawings toond writes (`output: "svg"`), for
// tests: the layers by id with their strokes, the stroke's width, and the
// camera in `<metadata id="toond-camera">`, which projects the model's
// points to the drawing's pixels. A small reader of what the format uses
// (groups, paths of M, L and Z), not a general SVG parser: tests that need
// one hand the file to librsvg or Chromium.
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace toond::test {

struct SvgStroke {
  std::vector<glm::dvec2> points;
  bool closed = false;
  std::string colour;  // its stroke attribute, else its layer's
};

struct SvgLayer {
  std::vector<SvgStroke> strokes;
  std::map<std::string, std::string> attributes;  // of its <g>
};

struct SvgFile {
  int width = 0, height = 0;
  std::map<std::string, SvgLayer> layers;  // by id
  nlohmann::json camera;                   // the metadata's JSON
  std::vector<std::string> path_data;      // every path's d, as written
};

// Throws std::runtime_error where the text is not such a drawing.
SvgFile read_svg_drawing(const std::string& text);

// A point of the model (or scene) to the drawing's pixels through the
// metadata's camera.
glm::dvec2 project_with(const nlohmann::json& camera, const glm::dvec3& point);

// The distance from p to the segment from a to b.
double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b);

// Every straight segment of the strokes (a closed stroke's last to first too).
std::vector<std::pair<glm::dvec2, glm::dvec2>> segments_of(const std::vector<SvgStroke>& strokes);

// The distance from p to the nearest of `segments`.
double distance_to(const std::vector<std::pair<glm::dvec2, glm::dvec2>>& segments, glm::dvec2 p);

}  // namespace toond::test
