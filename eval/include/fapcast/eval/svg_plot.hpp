#pragma once
// A small SVG line-plot writer for the command line's figures (no plotting dependency): stacked
// panels sharing one time axis, each with its own y axis, ticks and grid, one polyline per
// series, and one legend for the figure. Lives in tools/ because the libraries write no files.
#include <string>
#include <vector>

namespace fapcast {

// Values at x = x_start + i * x_step; NaN values leave a gap in the line.
struct PlotSeries {
  std::string name;  // legend entry; series with the same index share a colour across panels
  std::vector<double> values;
};

struct PlotPanel {
  std::string y_label;  // e.g. "lip height (mm)"
  std::vector<PlotSeries> series;
};

struct LinePlot {
  std::string title;
  std::string x_label;  // e.g. "time (s)"
  double x_start = 0.0;
  double x_step = 1.0;  // > 0
  std::vector<PlotPanel> panels;
  int width_px = 900;
  int panel_height_px = 220;
};

// The figure as a standalone SVG document (UTF-8). Text is XML-escaped. Throws
// std::invalid_argument when there is no panel or x_step is not positive.
std::string svg_line_plot(const LinePlot& plot);

// "Nice" tick positions (1, 2 or 5 times a power of ten) covering [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 5);

}  // namespace fapcast
