#pragma once
// A time-aligned label tier, as Praat and forced aligners produce: intervals (phones, words) or
// points (events). Times are seconds on the utterance's WAV timeline, kept as the double the file
// spelled (readers parse the shortest decimal, writers print the shortest decimal that reads back
// to the same double, so a round trip is exact); `to_sample` puts them on the sample grid.
#include "fapcast/core/sample_rate.hpp"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace fapcast {

// One labelled stretch of time [start_s, end_s), seconds; start_s <= end_s (TextGrid wants <).
struct Interval {
  double start_s = 0;
  double end_s = 0;
  std::string label;  // UTF-8; empty for an unlabelled gap (a pause, in Praat's habit)
  bool operator==(const Interval&) const = default;
};

// One labelled instant, seconds (a Praat TextTier point).
struct TimePoint {
  double time_s = 0;
  std::string mark;  // UTF-8
  bool operator==(const TimePoint&) const = default;
};

enum class TierKind { intervals, points };

// A named tier spanning [start_s, end_s]: intervals sorted and non-overlapping, or points with
// strictly increasing times, all inside the span. Only the vector matching `kind` is used.
struct LabelTier {
  std::string name;  // e.g. "phones", "words"
  TierKind kind = TierKind::intervals;
  double start_s = 0;
  double end_s = 0;
  std::vector<Interval> intervals;
  std::vector<TimePoint> points;
  bool operator==(const LabelTier&) const = default;
};

// The sample at time `seconds` on a timeline of `sample_rate`: round(seconds * rate),
// halves away from zero. Throws std::out_of_range if the result does not fit in int64.
std::int64_t to_sample(double seconds, SampleRate sample_rate);

// to_sample for a time read from the file `source`: a time no sample count holds is the file's
// fault, InputError (source, rule "time-off-sample-grid", detail `what`: to_sample's reason).
std::int64_t alignment_sample(double seconds, SampleRate sample_rate, const std::string& source, const std::string& what);

std::ostream& operator<<(std::ostream& out, const Interval& interval);
std::ostream& operator<<(std::ostream& out, const TimePoint& point);
std::ostream& operator<<(std::ostream& out, const LabelTier& tier);

}  // namespace fapcast
