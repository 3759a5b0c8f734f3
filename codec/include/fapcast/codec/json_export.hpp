#pragma once
// FAP track <-> JSON for web players (spec/json.md): a header (format, generator, name, frame
// rate, frame count, optional sample rate and FAPU) and one object per frame with its time in
// seconds, its WAV sample when a sample rate is given, its named FAP values and the viseme and
// expression fields. Output is deterministic: fixed key order, FAPs in FAP-number order.
#include "fapcast/core/sample_rate.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/codec/fapu_values.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fapcast {

inline constexpr std::string_view kFapJsonFormat = "fapcast-fap-json";
inline constexpr int kFapJsonVersion = 1;
// Sample rates and frame-rate terms the reader accepts, both 1..this.
inline constexpr std::int64_t kFapJsonMaxRate = 1'000'000;

struct FapJsonOptions {
  std::optional<SampleRate> sample_rate;  // adds each frame's WAV sample (frame_to_sample)
  std::optional<FapuValues> fapu;           // the face's FAPU lengths, when known
  std::string generator = "fapcast";        // who wrote the file
};

// Writes `seq` as JSON text (one header key per line, one frame per line, LF). Throws
// std::invalid_argument for an invalid frame rate or sample rate (1..kFapJsonMaxRate).
std::string write_fap_json(const FapSequence& seq, const FapJsonOptions& options = {});

struct FapJsonRead {
  FapSequence sequence;
  FapJsonOptions options;  // what the header said: sample rate, FAPU, generator
};

// Parses JSON written by write_fap_json (or by hand to spec/json.md). `source` names it in
// messages. Throws InputError with the rule broken: the byte offset for syntax errors, the JSON
// pointer of the offending value ("/frames/3/faps/open_jaw") for everything else.
FapJsonRead read_fap_json(std::string_view bytes, std::string_view source);

}  // namespace fapcast
