#pragma once
// How well one phone alignment of a recording agrees with another (a forced aligner's against a
// human's): the error of every phone boundary of the reference, in seconds, found by matching the
// two phone sequences (spec/recognise.md, "Scoring").
#include <cstddef>
#include <span>
#include <vector>

#include "fapcast/core/sample_rate.hpp"
#include "fapcast/phonetics/timed_phone.hpp"

namespace fapcast {

struct BoundaryAgreement {
  // |hypothesis - reference| of each internal reference boundary, seconds, in reference order.
  std::vector<double> errors_s;
  std::size_t reference_phones = 0;  // after merging identical neighbours (silences joined)
  std::size_t matched = 0;           // reference phones paired with a hypothesis phone of the same phone
  std::size_t substituted = 0;       // paired with another phone
  std::size_t deleted = 0;           // left without a partner

  // Share of the boundaries within `tolerance_s` (0 when there are none).
  double within(double tolerance_s) const;
};

// Scores `hypothesis` against `reference` (both on the timeline of one recording at
// `sample_rate`): identical neighbours are merged in each, the sequences matched by edit distance
// (a substitution inside one search viseme class costs half one across classes, an insertion or
// deletion one), and each reference boundary (the start of every reference phone but the first)
// is compared with the hypothesis boundaries the match leaves between its two phones' partners:
// the nearest of them.
BoundaryAgreement boundary_agreement(std::span<const TimedPhone> reference, std::span<const TimedPhone> hypothesis,
                                     SampleRate sample_rate);

}  // namespace fapcast
