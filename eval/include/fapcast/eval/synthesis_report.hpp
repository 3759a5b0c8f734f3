#pragma once
// How `fapcast eval synth` shows its result: the table, the JSON document and the Fig. 8-style
// lip-curve plots of an EvaluationReport. Formatting only; synth does the evaluation.
#include "fapcast/eval/svg_plot.hpp"

#include "fapcast/eval/synthesis_evaluation.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace fapcast {

// What produced the report, printed above the table and stored in the JSON.
struct EvaluationContext {
  std::string voice;        // the voice file
  std::uint64_t seed = 0;   // of the held-out recordings
  std::string command;      // the command line that reproduces the table
};

// One row per system: height / width / protrusion error % and correlation, lip-FP and all-FP
// RMS (mm), the lip height's median best lag (ms, + = the system behind the recording;
// median_lip_height_lag_ms), units per phone ("-" for a system that concatenates no units).
std::string format_evaluation_table(const EvaluationReport& report, const EvaluationContext& context);

nlohmann::json evaluation_json(const EvaluationReport& report, const EvaluationContext& context);

// Recorded against synthesised lip height, width and protrusion of one utterance (mm over
// seconds), one line per system; the title says SYNTHETIC.
LinePlot lip_curve_plot(const EvaluationReport& report, std::size_t utterance);

}  // namespace fapcast
