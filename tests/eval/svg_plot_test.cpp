// The SVG plot writer: well-formed, escaped, one polyline per run of finite values.
#include "fapcast/eval/svg_plot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cctype>
#include <string>
#include <vector>

namespace fapcast::cli {
namespace {

bool starts_with_entity(const std::string& s, std::size_t at) {
  for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"})
    if (s.compare(at, std::char_traits<char>::length(e), e) == 0) return true;
  return false;
}

// A tag's inside: a name, then name="value" attributes, then an optional '/'.
bool tag_is_well_formed(const std::string& tag) {
  std::size_t i = 0;
  auto name = [&] {
    const std::size_t b = i;
    while (i < tag.size() && (std::isalnum(static_cast<unsigned char>(tag[i])) || tag[i] == '-' || tag[i] == ':')) ++i;
    return i > b;
  };
  if (!name()) return false;
  while (i < tag.size() && tag[i] == ' ') {
    ++i;
    if (!name() || i + 1 >= tag.size() || tag[i] != '=' || tag[i + 1] != '"') return false;
    const std::size_t close = tag.find('"', i + 2);
    if (close == std::string::npos) return false;
    i = close + 1;
  }
  return i == tag.size() || (i + 1 == tag.size() && tag[i] == '/');
}

// Checks that every element is closed in order (XML nesting), that tags are well formed with
// quoted attribute values, and that no raw '&' sits in text. Returns "" or what is wrong.
std::string xml_problem(const std::string& s) {
  if (s.rfind("<?xml", 0) != 0) return "no XML declaration";
  std::vector<std::string> open;
  std::size_t i = s.find("<svg");
  while (i < s.size()) {
    const std::size_t lt = s.find('<', i);
    const std::size_t text_end = lt == std::string::npos ? s.size() : lt;
    for (std::size_t a = s.find('&', i); a < text_end; a = s.find('&', a + 1))
      if (!starts_with_entity(s, a)) return "raw & in text";
    if (lt == std::string::npos) break;
    const std::size_t gt = s.find('>', lt);
    if (gt == std::string::npos) return "unterminated tag";
    const std::string tag = s.substr(lt + 1, gt - lt - 1);
    if (tag.find('<') != std::string::npos) return "'<' inside a tag";
    if (tag.front() == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return "mismatched </" + tag.substr(1) + ">";
      open.pop_back();
    } else {
      if (!tag_is_well_formed(tag)) return "malformed tag <" + tag + ">";
      if (tag.back() != '/') open.push_back(tag.substr(0, tag.find_first_of(" /")));
    }
    i = gt + 1;
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

LinePlot figure() {
  LinePlot plot;
  plot.title = "SYNTHETIC lip height <recorded & synthesised>";
  plot.x_label = "time (s)";
  plot.x_step = 1.0 / 60;
  std::vector<double> a, b;
  for (int n = 0; n < 120; ++n) {
    a.push_back(5 + 4 * std::sin(0.1 * n));
    b.push_back(n >= 50 && n < 55 ? std::numeric_limits<double>::quiet_NaN() : 5 + 3 * std::sin(0.1 * n + 0.2));
  }
  plot.panels.push_back({"lip height (mm)", {{"recorded", a}, {"variable-length", b}}});
  plot.panels.push_back({"lip width (mm)", {{"recorded", a}, {"variable-length", a}}});
  return plot;
}

TEST(SvgPlot, IsWellFormedAndHasOnePolylinePerRun) {
  const std::string svg = svg_line_plot(figure());
  EXPECT_EQ(xml_problem(svg), "") << svg.substr(0, 2000);
  EXPECT_NE(svg.find("SYNTHETIC lip height &lt;recorded &amp; synthesised&gt;"), std::string::npos);
  // Panel 1: the recording (1 run) and a series with a gap (2 runs); panel 2: two lines.
  EXPECT_EQ(count(svg, "<polyline"), 5u);
  EXPECT_EQ(count(svg, "<g class=\"panel\">"), 2u);
  EXPECT_NE(svg.find("lip width (mm)"), std::string::npos);
  EXPECT_NE(svg.find(">variable-length</text>"), std::string::npos) << "legend";
  // The full recorded line has all 120 points.
  const std::size_t first = svg.find("<polyline");
  const std::string points = svg.substr(first, svg.find("\">", first) - first);
  EXPECT_EQ(count(points, ","), 120u);
  // Ticks on the time axis at 0, 0.2, ... (120 frames at 60 fps span 1.98 s).
  EXPECT_NE(svg.find(">0.2</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1.8</text>"), std::string::npos);
}

// A legend wider than the figure wraps onto more rows instead of running off the right edge, and
// the panels move down by as much: nothing is drawn over the legend.
TEST(SvgPlot, ALongLegendWrapsAndPushesThePanelsDown) {
  const LinePlot one_row = figure();
  LinePlot many = figure();
  for (auto& panel : many.panels)
    for (const char* name : {"own alignment (forced, transcript, accent US dictionary)",
                             "reference talker (SYNTHETIC), reference alignment", "a third long series name here"})
      panel.series.push_back({name, panel.series[0].values});
  const std::string svg = svg_line_plot(many);
  EXPECT_EQ(xml_problem(svg), "");
  // Every legend label (the text after a legend's line) ends inside the figure, at 7 px a character.
  const std::string entry = "stroke-width=\"2\"/>\n<text x=\"";
  std::size_t labels = 0;
  for (std::size_t at = svg.find(entry); at != std::string::npos; at = svg.find(entry, at + 1)) {
    const std::size_t text = at + entry.size() - 9;
    const double x = std::stod(svg.substr(text + 9));
    const std::size_t open = svg.find('>', text), close = svg.find("</text>", open);
    EXPECT_LE(x + 7 * static_cast<double>(close - open - 1), many.width_px) << svg.substr(text, 120);
    ++labels;
  }
  EXPECT_EQ(labels, 5u);
  // The first panel's frame is lower than with a one-row legend.
  const auto panel_top = [](const std::string& s) {
    const std::size_t g = s.find("<g class=\"panel\">");
    const std::size_t y = s.find(" y=\"", g);
    return std::stod(s.substr(y + 4));
  };
  EXPECT_GT(panel_top(svg), panel_top(svg_line_plot(one_row)) + 17);
}

TEST(SvgPlot, RefusesEmptyFiguresAndKeepsFlatOnesDrawable) {
  LinePlot empty;
  EXPECT_THROW(svg_line_plot(empty), std::invalid_argument);
  LinePlot flat = figure();
  flat.x_step = 0;
  EXPECT_THROW(svg_line_plot(flat), std::invalid_argument);
  flat = figure();
  flat.panels = {{"constant", {{"c", std::vector<double>(10, 3.0)}}}};
  const std::string svg = svg_line_plot(flat);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(SvgPlot, NiceTicks) {
  const auto unit = nice_ticks(0, 1, 5);
  ASSERT_EQ(unit.size(), 6u);
  for (std::size_t i = 0; i < unit.size(); ++i) EXPECT_NEAR(unit[i], 0.2 * static_cast<double>(i), 1e-12);
  const auto t = nice_ticks(-3.3, 17.1, 5);
  ASSERT_FALSE(t.empty());
  EXPECT_GE(t.front(), -3.3);
  EXPECT_LE(t.back(), 17.1);
  EXPECT_NEAR(t[1] - t[0], 5.0, 1e-12);
}

}  // namespace
}  // namespace fapcast::cli
