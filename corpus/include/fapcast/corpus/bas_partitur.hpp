#pragma once
// BAS Partitur files (.par, BPF), as WebMAUS and the EMU tools write them (spec/corpus.md
// "BAS Partitur").
#include "fapcast/corpus/alignment.hpp"

#include <string>
#include <string_view>

namespace fapcast {

// BAS Partitur (BPF): "KEY: fields" lines; SAM (the sample rate) from the header; tier MAU
// ("BEGIN DURATION WORD LABEL", samples) becomes interval tier "MAU" (a segment covers
// BEGIN .. BEGIN + DURATION + 1 samples), ORT ("WORD TEXT") the words tier "ORT" spanning each
// word's MAU segments.
Alignment read_partitur(std::string_view bytes, const std::string& source);

}  // namespace fapcast
