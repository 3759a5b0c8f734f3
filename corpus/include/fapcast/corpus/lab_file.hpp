#pragma once
// HTK and MOCHA-TIMIT label files (.lab): one segment per line, "start end label [score]".
// HTK writes times as integers in 100 ns units; MOCHA-TIMIT (and ESPS/Festival-style exports)
// as decimal seconds. The reader detects which: every time an integer -> HTK, otherwise seconds.
#include "fapcast/core/input_error.hpp"
#include "fapcast/corpus/label_tier.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

enum class LabTimeUnit {
  htk_100ns,  // integer multiples of 100 ns ("0 1200000 sil")
  seconds,    // decimal seconds ("0.0000 0.1200 sil")
};

struct LabFile {
  LabTimeUnit unit = LabTimeUnit::htk_100ns;
  std::vector<Interval> segments;             // seconds; sorted, non-overlapping, may be empty
  std::vector<std::optional<double>> scores;  // one per segment: HTK's optional 4th column
  // One per segment as read: its 1-based line in the file, for messages (the writer ignores it,
  // and equality does not compare it).
  std::vector<std::uint64_t> lines;
  bool operator==(const LabFile& other) const {
    return unit == other.unit && segments == other.segments && scores == other.scores;
  }
};

// Parses a .lab file. `unit` forces the time unit; nullopt detects it (see above). Blank lines
// are skipped. Throws InputError ("name:line: lab-...: detail").
LabFile read_lab(std::string_view bytes, const std::string& source,
                 std::optional<LabTimeUnit> unit = std::nullopt);

// The .lab text of `lab` in its unit (HTK times rounded to the nearest 100 ns, seconds in the
// shortest exact decimal), a score column where present. Throws std::invalid_argument for
// segments the reader would refuse (labels with whitespace, unordered or negative times).
std::string write_lab(const LabFile& lab);

// The interval tier of a .lab file's segments, spanning [0, last end], named `name`.
LabelTier to_tier(const LabFile& lab, std::string name);

}  // namespace fapcast
