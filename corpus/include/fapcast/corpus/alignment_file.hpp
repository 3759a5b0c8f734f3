#pragma once
// Any alignment file a real tool writes, read into timed phones: the format found from the
// content (the extension cross-checks it), the phone tier named by the user or found by rule,
// the label set named or found, and refusals with a reason when the result would be wrong.
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/corpus/alignment.hpp"
#include "fapcast/phonetics/label_sets.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

enum class AlignmentFormat { textgrid, htk_lab, seconds_lab, esps, timit, mlf, partitur, gentle };
std::string_view alignment_format_name(AlignmentFormat f);  // "TextGrid", "HTK .lab", ...

struct AlignmentFileOptions {
  std::optional<AlignmentFormat> format;     // skip detection (still checked against the content)
  std::optional<std::string> tier;           // --tier NAME
  std::optional<LabelSet> label_set;         // --phone-set NAME
  std::optional<SampleRate> sample_rate;     // the recording's (TIMIT offsets need it)
  std::optional<double> audio_seconds;       // the recording's length: units and coverage checks
  std::optional<std::string> utterance;      // the MLF entry to read: the recording's stem (default: the file's)
};

struct AlignedSegment {
  double start_s = 0;
  double end_s = 0;
  LabelKind kind = LabelKind::silence;
  Phone phone = Phone::SIL;  // SIL for silence and noise
  double release_s = 0;      // a closure joined with its release: where the release starts; else start_s
  std::string label;         // as the file spells it (joined segments: the first's)
};

struct AlignmentFile {
  AlignmentFormat format = AlignmentFormat::textgrid;
  Alignment alignment;   // every tier as read
  std::string tier;      // the phone tier's name
  LabelSet label_set = LabelSet::arpabet;
  std::vector<AlignedSegment> segments;  // the phone tier, mapped; joins applied, compounds split
  std::vector<std::string> notes;        // what was chosen and why, what was found (spn, untimed words)
};

// The segments of `tier` read in `set`: joins applied (a TIMIT closure with its release, an EMU
// aspiration with its stop), compound labels split evenly, silence and noise kept as such.
// Throws InputError (alignment-unknown-label) naming the interval, its times and its label.
std::vector<AlignedSegment> segments_of(const LabelTier& tier, LabelSet set, const std::string& source);

// Refusals after the choice: no phones, or phones and noises covering less than this share of
// the recording (or of the file's own span when the recording's length is not given).
inline constexpr double kMinSpeechCoverage = 0.05;

// Throws InputError: the format readers' rules, and alignment-format-mismatch,
// alignment-no-such-tier, alignment-tier-ambiguous, alignment-no-phone-tier,
// alignment-unknown-label, alignment-no-phones, alignment-low-coverage, lab-units-mismatch,
// timit-needs-rate, mlf-no-entry.
AlignmentFile read_alignment_file(std::string_view bytes, const std::string& path, const AlignmentFileOptions& options);

}  // namespace fapcast
