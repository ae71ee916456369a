#pragma once
// Time against error: which sweep points nobody beats on both, and an SVG
// with one panel per scene that marks them.
#include <cstddef>
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
  std::size_t bytes = 0;  // the PNG's size: what the answer costs on the wire
  bool is_default = false;
  bool on_front = false;  // filled by mark_pareto_front
};

// A point is on the front when no other point beats it: at least as
// accurate, not measurably slower and no larger, and more accurate,
// measurably faster or smaller. Errors and sizes are exact (the same image,
// the same error); times are noisy, so "measurably" means the
// interquartile ranges of the repeats do not overlap. Settings that draw
// the very same image (msaa 2 and 4 on llvmpipe) then share the front
// unless one is really faster, instead of the luckier timing pushing the
// other off; and PNG level 0, faster to encode but 25 times larger, beats
// nothing by speed alone. The plot's axes are time and error; size is the
// third axis, shown only in the CSV.
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
