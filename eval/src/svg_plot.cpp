#include "fapcast/eval/svg_plot.hpp"

#include "fapcast/core/xml_text.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fapcast {
namespace {

// Colour-blind-safe palette (Okabe-Ito), black first for the recording.
constexpr std::array<const char*, 8> kColours{"#000000", "#0072B2", "#D55E00", "#009E73",
                                              "#CC79A7", "#E69F00", "#56B4E9", "#F0E442"};

// A coordinate with two decimals: enough for pixels, short files.
std::string px(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

// A tick label without trailing zeros ("0.5", "12", "-0.25").
std::string label(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buffer;
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo) || target < 1) return {lo};
  const double raw = (hi - lo) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  std::vector<double> ticks;
  // Multiples of the step, not a running sum, so 0.6 does not drift to 0.6000000000000001 + ...
  const double first = std::ceil(lo / step - 1e-9);
  for (double k = first; k * step <= hi + 1e-9 * step; k += 1) ticks.push_back(k * step);
  return ticks;
}

std::string svg_line_plot(const LinePlot& plot) {
  if (plot.panels.empty()) throw std::invalid_argument("svg plot: no panels");
  if (!(plot.x_step > 0)) throw std::invalid_argument("svg plot: x step must be positive");
  const double left = 80, right = 20, gap = 45, bottom = 55;
  const double width = plot.width_px, panel_h = plot.panel_height_px;
  const double plot_w = width - left - right;

  std::size_t samples = 1;
  std::vector<std::string> legend;
  for (const auto& panel : plot.panels)
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      samples = std::max(samples, panel.series[s].values.size());
      if (s >= legend.size()) legend.push_back(panel.series[s].name);
    }
  // Legend entries left to right under the title, a new row (18 px lower) where the next one
  // would pass the right margin; the panels start below the last row.
  struct LegendEntry {
    double x, y;
  };
  std::vector<LegendEntry> entries;
  double lx = left, ly = 40;
  for (const std::string& name : legend) {
    const double w = 40 + 7.0 * static_cast<double>(name.size());
    if (lx > left && lx + w - 10 > width - right) lx = left, ly += 18;
    entries.push_back({lx, ly});
    lx += w;
  }
  const double top = ly + 20;
  const double height = top + static_cast<double>(plot.panels.size()) * (panel_h + gap) - gap + bottom;
  const double x_lo = plot.x_start;
  const double x_hi = plot.x_start + static_cast<double>(std::max<std::size_t>(samples, 2) - 1) * plot.x_step;
  auto x_px = [&](double x) { return left + (x - x_lo) / (x_hi - x_lo) * plot_w; };

  std::ostringstream svg;
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << px(height)
      << "\" viewBox=\"0 0 " << width << ' ' << px(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << px(width / 2) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
      << escape_xml(plot.title) << "</text>\n";
  for (std::size_t s = 0; s < legend.size(); ++s) {
    const char* colour = kColours[s % kColours.size()];
    const auto [ex, ey] = entries[s];
    svg << "<line x1=\"" << px(ex) << "\" y1=\"" << px(ey) << "\" x2=\"" << px(ex + 24) << "\" y2=\"" << px(ey)
        << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n"
        << "<text x=\"" << px(ex + 30) << "\" y=\"" << px(ey + 4) << "\">" << escape_xml(legend[s]) << "</text>\n";
  }

  for (std::size_t p = 0; p < plot.panels.size(); ++p) {
    const auto& panel = plot.panels[p];
    const double y0 = top + static_cast<double>(p) * (panel_h + gap);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& s : panel.series)
      for (const double v : s.values)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (!(hi >= lo)) lo = 0, hi = 1;  // no data: an empty frame
    if (hi - lo < 1e-12) lo -= 0.5, hi += 0.5;
    const double pad = 0.05 * (hi - lo);
    lo -= pad;
    hi += pad;
    auto y_px = [&](double y) { return y0 + panel_h - (y - lo) / (hi - lo) * panel_h; };

    svg << "<g class=\"panel\">\n";
    for (const double t : nice_ticks(lo, hi)) {
      svg << "<line x1=\"" << px(left) << "\" y1=\"" << px(y_px(t)) << "\" x2=\"" << px(left + plot_w)
          << "\" y2=\"" << px(y_px(t)) << "\" stroke=\"#dddddd\"/>\n"
          << "<text x=\"" << px(left - 6) << "\" y=\"" << px(y_px(t) + 4) << "\" text-anchor=\"end\">"
          << label(t) << "</text>\n";
    }
    for (const double t : nice_ticks(x_lo, x_hi, 10)) {
      svg << "<line x1=\"" << px(x_px(t)) << "\" y1=\"" << px(y0 + panel_h) << "\" x2=\"" << px(x_px(t))
          << "\" y2=\"" << px(y0 + panel_h + 5) << "\" stroke=\"black\"/>\n"
          << "<text x=\"" << px(x_px(t)) << "\" y=\"" << px(y0 + panel_h + 18)
          << "\" text-anchor=\"middle\">" << label(t) << "</text>\n";
    }
    svg << "<rect x=\"" << px(left) << "\" y=\"" << px(y0) << "\" width=\"" << px(plot_w) << "\" height=\""
        << px(panel_h) << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text transform=\"translate(" << px(18) << ',' << px(y0 + panel_h / 2)
        << ") rotate(-90)\" text-anchor=\"middle\">" << escape_xml(panel.y_label) << "</text>\n";
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const auto& values = panel.series[s].values;
      const char* colour = kColours[s % kColours.size()];
      // One polyline per run of finite values.
      for (std::size_t i = 0; i < values.size();) {
        while (i < values.size() && !std::isfinite(values[i])) ++i;
        if (i == values.size()) break;
        svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\" points=\"";
        for (bool first = true; i < values.size() && std::isfinite(values[i]); ++i, first = false)
          svg << (first ? "" : " ") << px(x_px(x_lo + static_cast<double>(i) * plot.x_step)) << ','
              << px(y_px(values[i]));
        svg << "\"><title>" << escape_xml(panel.series[s].name) << "</title></polyline>\n";
      }
    }
    svg << "</g>\n";
  }
  svg << "<text x=\"" << px(left + plot_w / 2) << "\" y=\"" << px(height - 12)
      << "\" text-anchor=\"middle\">" << escape_xml(plot.x_label) << "</text>\n</svg>\n";
  return svg.str();
}

}  // namespace fapcast
