#include "pareto_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace toond::bench {
namespace {

std::string fmt(const char* pattern, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

const char* colour_of(const std::string& family) {
  static const std::map<std::string, const char*> colours = {
      {"msaa×ss", "#1f77b4"}, {"lod", "#d62728"}, {"shadow map", "#2ca02c"}, {"png", "#9467bd"}};
  const auto it = colours.find(family);
  return it == colours.end() ? "#7f7f7f" : it->second;
}

// A tick step of 1, 2 or 5 × 10^k giving about `count` ticks over `span`.
double nice_step(double span, int count) {
  const double raw = span / count;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * p) return m * p;
  return 10.0 * p;
}

}  // namespace

void mark_pareto_front(std::vector<PlotPoint>& points) {
  auto faster = [](const PlotPoint& a, const PlotPoint& b) { return a.time_high_ms < b.time_low_ms; };
  for (PlotPoint& p : points) {
    p.on_front = std::none_of(points.begin(), points.end(), [&](const PlotPoint& q) {
      return q.error <= p.error && q.bytes <= p.bytes && !faster(p, q) &&
             (q.error < p.error || q.bytes < p.bytes || faster(q, p));
    });
  }
}

std::string svg_time_vs_error(const std::vector<PlotPanel>& panels, const std::string& caption) {
  constexpr int kPanelW = 460, kPanelH = 320, kLeft = 64, kRight = 16, kTop = 34, kBottom = 46;
  const int columns = 2;
  const int rows = static_cast<int>((panels.size() + 1) / 2);
  const int legend_h = 40;
  const int width = columns * kPanelW;
  const int height = rows * kPanelH + legend_h + 24;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const PlotPanel& panel = panels[i];
    const int ox = static_cast<int>(i % 2) * kPanelW, oy = static_cast<int>(i / 2) * kPanelH;
    const int pw = kPanelW - kLeft - kRight, ph = kPanelH - kTop - kBottom;
    double tmin = 1e300, tmax = 0, emax = 0;
    for (const PlotPoint& p : panel.points) {
      tmin = std::min(tmin, p.time_ms);
      tmax = std::max(tmax, p.time_ms);
      emax = std::max(emax, p.error);
    }
    if (panel.points.empty()) tmin = 1, tmax = 10;
    const double lx0 = std::floor(std::log10(std::max(tmin, 1e-3)) * 4) / 4;
    const double lx1 = std::max(std::ceil(std::log10(std::max(tmax, 1e-3)) * 4) / 4, lx0 + 0.25);
    const double ystep = nice_step(emax > 0 ? emax : 1.0, 5);
    const double ymax = std::ceil((emax > 0 ? emax : 1.0) / ystep) * ystep;
    auto X = [&](double t) { return ox + kLeft + (std::log10(std::max(t, 1e-3)) - lx0) / (lx1 - lx0) * pw; };
    auto Y = [&](double e) { return oy + kTop + ph - e / ymax * ph; };
    svg << "<text x=\"" << ox + kLeft + pw / 2 << "\" y=\"" << oy + 18
        << "\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" << escape(panel.title) << "</text>\n";
    svg << "<rect x=\"" << ox + kLeft << "\" y=\"" << oy + kTop << "\" width=\"" << pw << "\" height=\"" << ph
        << "\" fill=\"none\" stroke=\"#444\"/>\n";
    // x ticks at 1, 2, 5 × 10^k
    for (int decade = static_cast<int>(std::floor(lx0)); decade <= static_cast<int>(std::ceil(lx1)); ++decade) {
      for (double m : {1.0, 2.0, 5.0}) {
        const double t = m * std::pow(10.0, decade);
        const double l = std::log10(t);
        if (l < lx0 - 1e-9 || l > lx1 + 1e-9) continue;
        const double x = X(t);
        svg << "<line x1=\"" << x << "\" y1=\"" << oy + kTop << "\" x2=\"" << x << "\" y2=\"" << oy + kTop + ph
            << "\" stroke=\"#ddd\"/>\n<text x=\"" << x << "\" y=\"" << oy + kTop + ph + 14
            << "\" text-anchor=\"middle\">" << fmt("%g", t) << "</text>\n";
      }
    }
    for (double e = 0; e <= ymax + 1e-12; e += ystep) {
      const double y = Y(e);
      svg << "<line x1=\"" << ox + kLeft << "\" y1=\"" << y << "\" x2=\"" << ox + kLeft + pw << "\" y2=\"" << y
          << "\" stroke=\"#ddd\"/>\n<text x=\"" << ox + kLeft - 4 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
          << fmt("%g", e) << "</text>\n";
    }
    svg << "<text x=\"" << ox + kLeft + pw / 2 << "\" y=\"" << oy + kTop + ph + 32
        << "\" text-anchor=\"middle\">server time per render, ms (log)</text>\n";
    svg << "<text transform=\"translate(" << ox + 14 << "," << oy + kTop + ph / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << escape(panel.error_label) << "</text>\n";
    std::vector<PlotPoint> front;
    for (const PlotPoint& p : panel.points)
      if (p.on_front) front.push_back(p);
    std::sort(front.begin(), front.end(), [](const PlotPoint& a, const PlotPoint& b) { return a.time_ms < b.time_ms; });
    if (front.size() > 1) {
      svg << "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\" points=\"";
      for (const PlotPoint& p : front) svg << X(p.time_ms) << "," << Y(p.error) << " ";
      svg << "\"/>\n";
    }
    for (const PlotPoint& p : panel.points) {
      svg << "<circle cx=\"" << X(p.time_ms) << "\" cy=\"" << Y(p.error) << "\" r=\"" << (p.on_front ? 4.5 : 3)
          << "\" fill=\"" << colour_of(p.family) << "\" fill-opacity=\"" << (p.on_front ? 1.0 : 0.45) << "\"><title>"
          << escape(p.label) << ": " << fmt("%.2f ms", p.time_ms) << ", error " << fmt("%.4g", p.error)
          << (p.on_front ? " (front)" : "") << "</title></circle>\n";
      if (p.is_default) {
        svg << "<circle cx=\"" << X(p.time_ms) << "\" cy=\"" << Y(p.error)
            << "\" r=\"8\" fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"/>\n";
      }
      if (p.on_front) {
        svg << "<text x=\"" << X(p.time_ms) + 6 << "\" y=\"" << Y(p.error) - 5 << "\" font-size=\"9\" fill=\"#333\">"
            << escape(p.label) << "</text>\n";
      }
    }
  }
  // Legend.
  const int ly = rows * kPanelH + 16;
  int lx = 16;
  for (const char* family : {"msaa×ss", "lod", "shadow map", "png"}) {
    svg << "<circle cx=\"" << lx << "\" cy=\"" << ly << "\" r=\"4.5\" fill=\"" << colour_of(family) << "\"/>"
        << "<text x=\"" << lx + 8 << "\" y=\"" << ly + 4 << "\">" << escape(family) << "</text>\n";
    lx += 110;
  }
  svg << "<circle cx=\"" << lx << "\" cy=\"" << ly << "\" r=\"8\" fill=\"none\" stroke=\"#000\"/><text x=\"" << lx + 12
      << "\" y=\"" << ly + 4 << "\">default settings</text>\n";
  lx += 130;
  svg << "<line x1=\"" << lx << "\" y1=\"" << ly << "\" x2=\"" << lx + 24 << "\" y2=\"" << ly
      << "\" stroke=\"#000\" stroke-dasharray=\"4 3\"/><text x=\"" << lx + 30 << "\" y=\"" << ly + 4
      << "\">Pareto front (labelled)</text>\n";
  svg << "<text x=\"16\" y=\"" << ly + 22 << "\" fill=\"#555\">" << escape(caption) << "</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace toond::bench
