#pragma once
// Time against error: which sweep points nobody beats on both, and an SVG
// with one panel per scene that marks them.
#include <string>
#include <vector>

namespace toond::bench {

struct PlotPoint {
  std::string label;   // e.g. "msaa 4 ss 1"
  std::string family;  // the knob swept: msaa×ss, lod, shadow map, png
  double time_ms = 0;
  double error = 0;
  bool is_default = false;
  bool on_front = false;  // filled by mark_pareto_front
};

// A point is on the front when no other point is at least as fast and at
// least as accurate, and strictly better in one of the two.
void mark_pareto_front(std::vector<PlotPoint>& points);

struct PlotPanel {
  std::string title;
  std::string error_label;  // the y axis
  std::vector<PlotPoint> points;
};

// Panels side by side (two per row); x is server time per render on a log
// scale, y the panel's error. Front points are joined by a line, the
// default quality is ringed.
std::string svg_time_vs_error(const std::vector<PlotPanel>& panels, const std::string& caption);

}  // namespace toond::bench
