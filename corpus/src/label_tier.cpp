#include "fapcast/corpus/label_tier.hpp"

#include "fapcast/core/input_error.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fapcast {

std::int64_t to_sample(double seconds, SampleRate sample_rate) {
  const double samples = std::round(seconds * static_cast<double>(sample_rate.hz));
  // 2^63 is exactly representable; anything at or beyond it (or NaN) does not fit.
  if (!(std::fabs(samples) < 9223372036854775808.0)) {
    std::ostringstream what;
    what << "time " << seconds << " s is off the sample grid of " << sample_rate.hz << " Hz";
    throw std::out_of_range(what.str());
  }
  return static_cast<std::int64_t>(samples);
}

std::int64_t alignment_sample(double seconds, SampleRate sample_rate, const std::string& source, const std::string& what) {
  try {
    return to_sample(seconds, sample_rate);
  } catch (const std::out_of_range& e) {
    throw InputError({source, std::nullopt, std::nullopt}, "time-off-sample-grid", (what.empty() ? "" : what + ": ") + e.what());
  }
}

std::ostream& operator<<(std::ostream& out, const Interval& interval) {
  return out << "[" << interval.start_s << ", " << interval.end_s << ") \"" << interval.label << "\"";
}

std::ostream& operator<<(std::ostream& out, const TimePoint& point) {
  return out << point.time_s << " \"" << point.mark << "\"";
}

std::ostream& operator<<(std::ostream& out, const LabelTier& tier) {
  out << (tier.kind == TierKind::intervals ? "IntervalTier" : "TextTier") << " \"" << tier.name
      << "\" [" << tier.start_s << ", " << tier.end_s << "]";
  if (tier.kind == TierKind::intervals) {
    for (const Interval& i : tier.intervals) out << "\n  " << i;
  } else {
    for (const TimePoint& p : tier.points) out << "\n  " << p;
  }
  return out;
}

}  // namespace fapcast
