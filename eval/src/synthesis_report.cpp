#include "fapcast/eval/synthesis_report.hpp"

#include "fapcast/core/synthetic_label.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace fapcast {
namespace {

std::string fixed(double v, int decimals) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

std::string pad_left(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

std::string pad_right(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

// The scorer's lip curves are in metres (synthesis_score.hpp); the report speaks mm.
double mm(double metres) { return 1000.0 * metres; }

nlohmann::json agreement_json(const CurveAgreement& a) {
  return {{"error_percent", a.mean_error_percent},
          {"mean_abs_difference_mm", mm(a.mean_abs_difference)},
          {"correlation", a.correlation},
          {"frames", a.frames}};
}

}  // namespace

std::string format_evaluation_table(const EvaluationReport& report, const EvaluationContext& context) {
  std::ostringstream out;
  out << kSyntheticLabel << "\n"
      << "held-out sentences: " << report.utterances.size() << " (seed " << context.seed << "), "
      << report.phones << " phones, " << report.frames << " frames at 60 fps; voice " << context.voice << "\n"
      << "errors: mean |recorded - synthesised| of each curve normalised by its maximum (%, the paper's) "
         "and in mm; r: correlation; jaw: the chin (FP 2.1) below the temples; RMS over feature-point "
         "positions on the target face\n";
  const std::vector<std::string> header{"system",    "height %",  "width %",  "protr. %",   "height mm",
                                        "width mm",  "protr. mm", "r height", "r width",    "r protr.",
                                        "jaw mm",    "r jaw",     "lip RMS mm", "all RMS mm", "lag ms",
                                        "units/phone"};
  std::size_t name_width = header[0].size();
  for (const auto& s : report.systems) name_width = std::max(name_width, s.name.size());
  out << pad_right(header[0], name_width);
  for (std::size_t i = 1; i < header.size(); ++i) out << "  " << pad_left(header[i], header[i].size());
  out << "\n";
  for (std::size_t system = 0; system < report.systems.size(); ++system) {
    const auto& s = report.systems[system];
    const auto& l = s.score.lips;
    const auto lag = median_lip_height_lag_ms(report, system);
    const bool jaw = s.score.jaw.frames > 0;  // the face has FP 2.1
    const std::vector<std::string> cells{fixed(l.height.mean_error_percent, 2), fixed(l.width.mean_error_percent, 2),
                                         fixed(l.protrusion.mean_error_percent, 2),
                                         fixed(mm(l.height.mean_abs_difference), 3), fixed(mm(l.width.mean_abs_difference), 3),
                                         fixed(mm(l.protrusion.mean_abs_difference), 3), fixed(l.height.correlation, 3),
                                         fixed(l.width.correlation, 3), fixed(l.protrusion.correlation, 3),
                                         jaw ? fixed(mm(s.score.jaw.mean_abs_difference), 3) : "-",
                                         jaw ? fixed(s.score.jaw.correlation, 3) : "-",
                                         fixed(s.score.lip_rms_mm, 2), fixed(s.score.all_rms_mm, 2),
                                         lag ? fixed(*lag, 0) : "-",
                                         s.units_per_phone > 0 ? fixed(s.units_per_phone, 3) : "-"};
    out << pad_right(s.name, name_width);
    for (std::size_t i = 0; i < cells.size(); ++i) out << "  " << pad_left(cells[i], header[i + 1].size());
    out << "\n";
  }
  if (!context.command.empty()) out << "reproduce: " << context.command << "\n";
  return out.str();
}

nlohmann::json evaluation_json(const EvaluationReport& report, const EvaluationContext& context) {
  nlohmann::json systems = nlohmann::json::array();
  for (std::size_t system = 0; system < report.systems.size(); ++system) {
    const auto& s = report.systems[system];
    const auto lag = median_lip_height_lag_ms(report, system);
    systems.push_back({{"name", s.name},
                       {"lip_height", agreement_json(s.score.lips.height)},
                       {"lip_width", agreement_json(s.score.lips.width)},
                       {"lip_protrusion", agreement_json(s.score.lips.protrusion)},
                       {"jaw_opening_chin", s.score.jaw.frames > 0 ? agreement_json(s.score.jaw) : nlohmann::json()},
                       {"lip_fp_rms_mm", s.score.lip_rms_mm},
                       {"all_fp_rms_mm", s.score.all_rms_mm},
                       {"frames", s.score.frames},
                       {"lip_height_lag_ms", lag ? nlohmann::json(*lag) : nlohmann::json()},
                       {"units_per_phone", s.units_per_phone}});
  }
  nlohmann::json utterances = nlohmann::json::array();
  for (const auto& u : report.utterances) utterances.push_back({{"id", u.id}, {"text", u.text}, {"frames", u.recorded.size()}});
  return {{"format", "fapcast eval synth"},
          {"synthetic", true},
          {"label", kSyntheticLabel},
          {"voice", context.voice},
          {"seed", context.seed},
          {"command", context.command},
          {"phones", report.phones},
          {"frames", report.frames},
          {"utterances", std::move(utterances)},
          {"systems", std::move(systems)}};
}

LinePlot lip_curve_plot(const EvaluationReport& report, std::size_t utterance) {
  if (utterance >= report.utterances.size()) throw std::out_of_range("lip curve plot: no such utterance");
  const auto& u = report.utterances[utterance];
  LinePlot plot;
  plot.title = "SYNTHETIC held-out " + u.id + ": \"" + u.text + "\" - recorded vs synthesised";
  plot.x_label = "time (s)";
  plot.x_step = 1.0 / 60.0;
  const std::vector<std::pair<std::string, std::vector<double> LipCurves::*>> measures{
      {"lip height (mm)", &LipCurves::height},
      {"lip width (mm)", &LipCurves::width},
      {"lip protrusion (mm)", &LipCurves::protrusion}};
  for (const auto& [label, member] : measures) {
    PlotPanel panel{label, {{"recorded", u.recorded.*member}}};
    for (std::size_t s = 0; s < u.synthesised.size() && s < report.systems.size(); ++s)
      panel.series.push_back({report.systems[s].name, u.synthesised[s].*member});
    plot.panels.push_back(std::move(panel));
  }
  return plot;
}

}  // namespace fapcast
