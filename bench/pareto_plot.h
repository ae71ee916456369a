#pragma once
// Time against error: which sweep points nobody beats on both, and an SVG
// with one panel per scene that marks them.
#include <string>
#include <vector>

namespace toond::bench {

struct PlotPoint {
  std::string label;   // e.g. "msaa 4 ss 1"
  std::string family;  // the knob swept: msaa×ss, lod, shadow map, png
  double time_ms = 0;  // the median of the repeats
  // The interquartile range of the repeats' times (both time_ms when there
  // is one repeat): the spread the front allows for.
  double time_low_ms = 0;
  double time_high_ms = 0;
  double error = 0;
  bool is_default = false;
  bool on_front = false;  // filled by mark_pareto_front
};

// A point is on the front when no other point beats it: at least as
// accurate and not measurably slower, and more accurate or measurably
// faster. Errors are exact (the same image, the same error); times are
// noisy, so "measurably" means the interquartile ranges do not overlap.
// Settings that draw the very same image (msaa 2 and 4 on llvmpipe) then
// share the front unless one is really faster, instead of the luckier
// timing pushing the other off.
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
