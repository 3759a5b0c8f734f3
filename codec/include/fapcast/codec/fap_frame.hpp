#pragma once
// One frame of facial animation parameters, and a sequence of them at a frame rate.
#include "fapcast/codec/fap_table.hpp"
#include "fapcast/core/frame_rate.hpp"

#include <array>
#include <bitset>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace fapcast {

// FAP 1: a blend of two of the 14 MPEG-4 visemes (0 = none).
struct VisemeField {
  std::uint8_t select1 = 0;  // 0..14
  std::uint8_t select2 = 0;  // 0..14
  std::uint8_t blend = 0;    // 0..63; 63 = all select1
  bool def = false;          // viseme_def: the frame defines the viseme rather than plays it
  bool operator==(const VisemeField&) const = default;
};

// FAP 2: a blend of two of the six universal expressions (0 = none).
struct ExpressionField {
  std::uint8_t select1 = 0;     // 0..6: none, joy, sadness, anger, fear, disgust, surprise
  std::uint8_t intensity1 = 0;  // 0..63
  std::uint8_t select2 = 0;     // 0..6
  std::uint8_t intensity2 = 0;  // 0..63
  bool init_face = false;
  bool def = false;             // expression_def
  bool operator==(const ExpressionField&) const = default;
};

// Which of FAPs 1..68 a frame carries.
class FapMask {
 public:
  bool test(int fap) const { return bits_.test(fap_slot(fap)); }
  FapMask& set(int fap, bool on = true) {
    bits_.set(fap_slot(fap), on);
    return *this;
  }
  int count() const { return static_cast<int>(bits_.count()); }
  bool none() const { return bits_.none(); }
  static FapMask all() { return FapMask{}.flip(); }
  FapMask& flip() {
    bits_.flip();
    return *this;
  }
  bool operator==(const FapMask&) const = default;

 private:
  std::bitset<kFapCount> bits_;
};

std::ostream& operator<<(std::ostream& out, const FapMask& mask);  // "{3 open_jaw, 4 ...}"

// One frame. Values are integers in the FAP's FAPU; only masked FAPs carry meaning, and the
// value of an unmasked FAP is kept at 0 so that frames compare by content.
struct FapFrame {
  FapMask mask;
  std::array<std::int32_t, kFapCount> values{};  // values[n-1] is FAP n; 0 and 1 unused
  VisemeField viseme;                            // FAP 1, meaningful when mask.test(1)
  ExpressionField expression;                    // FAP 2, meaningful when mask.test(2)

  std::int32_t value(int fap) const { return values[fap_slot(fap)]; }
  // Sets a low-level FAP (3..68) and marks it in the mask.
  FapFrame& set(int fap, std::int32_t v) {
    values[fap_slot(fap)] = v;
    mask.set(fap);
    return *this;
  }
  bool operator==(const FapFrame&) const = default;
};

// Prints the masked content: "{open_jaw=120 lower_t_midlip=-3 viseme=(1,0,63,0)}".
std::ostream& operator<<(std::ostream& out, const FapFrame& frame);

// A track: frames 0..N-1 at one frame rate. `name` is the free-text name a .fap header carries.
struct FapSequence {
  std::string name;
  FrameRate rate;
  std::vector<FapFrame> frames;

  bool operator==(const FapSequence&) const = default;
};

// Prints the header and, for short sequences, every frame (so a failing test shows what differs).
std::ostream& operator<<(std::ostream& out, const FapSequence& seq);

}  // namespace fapcast
