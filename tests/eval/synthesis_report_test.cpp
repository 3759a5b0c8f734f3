// The table, JSON and plots of `fapcast eval synth`, from a hand-made report.
#include "fapcast/eval/synthesis_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fapcast::cli {
namespace {

EvaluationReport report() {
  EvaluationReport r;
  r.phones = 40;
  r.frames = 120;
  SystemReport a{"variable-length", {}, 0.35};
  a.score.lips.height = {4.5, 0.91, 120, 0.000625};  // the scorer's curves are in metres
  a.score.jaw = {7.5, 0.875, 120, 0.0003125};
  a.score.lip_rms_mm = 1.25;
  a.score.all_rms_mm = 0.75;
  SystemReport b{"dominance", {}, 0.0};
  r.systems = {a, b};
  UtteranceCurves u{"heldout01", "Bob & \"Jo\" <said>", {}, {{}, {}}};
  for (int n = 0; n < 120; ++n) {
    const double v = 10 + 5 * std::sin(0.1 * n);
    u.recorded.push_back({v, 50.0, 90.0});
    u.synthesised[0].push_back({v + 1, 49.0, 90.5});
    u.synthesised[1].push_back({v - 1, 51.0, 89.5});
  }
  r.utterances.push_back(u);
  return r;
}

TEST(SynthesisReport, TableHasOneRowPerSystemAndSaysSynthetic) {
  const std::string t = format_evaluation_table(report(), {"v.fapv", 2, "fapcast eval synth --seed 2"});
  EXPECT_NE(t.find("SYNTHETIC"), std::string::npos);
  EXPECT_NE(t.find("variable-length"), std::string::npos);
  EXPECT_NE(t.find("4.50"), std::string::npos);
  EXPECT_NE(t.find("0.910"), std::string::npos);
  EXPECT_NE(t.find("0.350"), std::string::npos);
  EXPECT_NE(t.find("height mm"), std::string::npos);
  EXPECT_NE(t.find("0.625"), std::string::npos);
  EXPECT_NE(t.find("reproduce: fapcast eval synth --seed 2"), std::string::npos);
  const auto row = t.substr(t.find("\ndominance"));
  EXPECT_NE(row.find(" -\n"), std::string::npos) << "no units for the dominance model: " << row;
  EXPECT_NE(t.find("r jaw"), std::string::npos);
  EXPECT_NE(t.find("0.875"), std::string::npos) << "the jaw's r";
  EXPECT_NE(t.find("0.312"), std::string::npos) << "the jaw's error in mm";
  EXPECT_NE(row.find(" -  "), std::string::npos) << "no jaw scored for a face without FP 2.1: " << row;

  const auto j = evaluation_json(report(), {"v.fapv", 2, ""});
  EXPECT_TRUE(j["synthetic"].get<bool>());
  EXPECT_EQ(j["systems"].size(), 2u);
  EXPECT_DOUBLE_EQ(j["systems"][0]["lip_height"]["error_percent"].get<double>(), 4.5);
  EXPECT_NEAR(j["systems"][0]["lip_height"]["mean_abs_difference_mm"].get<double>(), 0.625, 1e-12);
  EXPECT_DOUBLE_EQ(j["systems"][0]["lip_fp_rms_mm"].get<double>(), 1.25);
  EXPECT_DOUBLE_EQ(j["systems"][0]["jaw_opening_chin"]["correlation"].get<double>(), 0.875);
  EXPECT_TRUE(j["systems"][1]["jaw_opening_chin"].is_null());
}

// The lag column: the median over utterances of the delay that best aligns each system's lip
// height with the recording (+ = the system behind).
TEST(SynthesisReport, LagIsTheMedianDelayOfTheLipHeight) {
  EvaluationReport r = report();
  EXPECT_NEAR(*median_lip_height_lag_ms(r, 0), 0.0, 1e-9) << "an offset is no delay";
  // Two more utterances: the first system one frame (16.7 ms) behind in both, the second two
  // frames ahead in one and on time in the other.
  for (int k = 0; k < 2; ++k) {
    UtteranceCurves u{"heldout0" + std::to_string(k + 2), "x", {}, {{}, {}}};
    for (int n = 0; n < 120; ++n) {
      const auto height = [](int i) { return 10 + 5 * std::sin(0.15 * i) + std::sin(0.4 * i); };
      u.recorded.push_back({height(n), 50.0, 90.0});
      u.synthesised[0].push_back({height(n - 1), 50.0, 90.0});
      u.synthesised[1].push_back({height(k == 0 ? n + 2 : n), 50.0, 90.0});
    }
    r.utterances.push_back(u);
  }
  EXPECT_NEAR(*median_lip_height_lag_ms(r, 0), 1000.0 / 60, 1.0) << "the median of 0, 16.7, 16.7";
  EXPECT_NEAR(*median_lip_height_lag_ms(r, 1), 0.0, 1.0) << "the median of 0, -33.3, 0";
  EXPECT_THROW((void)median_lip_height_lag_ms(r, 2), std::out_of_range);
  const std::string t = format_evaluation_table(r, {"v.fapv", 2, ""});
  EXPECT_NE(t.find("lag ms"), std::string::npos) << t;
  EXPECT_NE(t.substr(t.find("\nvariable-length")).find("  17  "), std::string::npos) << t;
  const auto j = evaluation_json(r, {"v.fapv", 2, ""});
  EXPECT_NEAR(j["systems"][0]["lip_height_lag_ms"].get<double>(), 1000.0 / 60, 1.0);
  EXPECT_TRUE(evaluation_json(EvaluationReport{{report().systems}, {}, 0, 0}, {"v.fapv", 2, ""})["systems"][0]["lip_height_lag_ms"].is_null())
      << "no utterance, no lag";
}

TEST(SynthesisReport, LipPlotHasThreePanelsAndALinePerSystem) {
  const LinePlot plot = lip_curve_plot(report(), 0);
  EXPECT_NE(plot.title.find("SYNTHETIC"), std::string::npos);
  ASSERT_EQ(plot.panels.size(), 3u);
  for (const auto& p : plot.panels) {
    ASSERT_EQ(p.series.size(), 3u);
    EXPECT_EQ(p.series[0].name, "recorded");
    EXPECT_EQ(p.series[2].name, "dominance");
    EXPECT_EQ(p.series[1].values.size(), 120u);
  }
  EXPECT_DOUBLE_EQ(plot.panels[1].series[1].values[0], 49.0) << "width panel, first system";
  const std::string svg = svg_line_plot(plot);
  EXPECT_NE(svg.find("Bob &amp; &quot;Jo&quot; &lt;said&gt;"), std::string::npos);
  std::size_t polylines = 0;
  for (auto p = svg.find("<polyline"); p != std::string::npos; p = svg.find("<polyline", p + 1)) ++polylines;
  EXPECT_EQ(polylines, 9u);
  EXPECT_THROW(lip_curve_plot(report(), 1), std::out_of_range);
}

}  // namespace
}  // namespace fapcast::cli
