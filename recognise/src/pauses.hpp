#pragma once
// Where a long recording may be cut for alignment piece by piece: the middles of its long
// pauses, found by frame energy (spec/recognise.md, "Long recordings"). A private header of
// fapcast::recognise.
#include <cstdint>
#include <span>
#include <vector>

namespace fapcast {

struct PauseSettings {
  std::int64_t frame_samples = 160;    // 10 ms at 16 kHz
  int min_pause_frames = 25;           // a pause lasts at least 250 ms
  // A frame is quiet below floor + share * (speech level - floor), where the floor is the 10th
  // and the speech level the 90th percentile of the frames' energies (dB).
  double quiet_share = 0.2;
  // A signal whose speech level is less than this above its floor has no pauses (dB).
  double min_contrast_db = 10.0;
};

// A quiet stretch [start, end) in samples of the signal.
struct Pause {
  std::int64_t start = 0;
  std::int64_t end = 0;
};

// The pauses of `samples` in time order.
std::vector<Pause> find_pauses(std::span<const std::int16_t> samples, const PauseSettings& settings = {});

// Cut points (samples, increasing, strictly inside the signal) that split it into pieces of at
// least `min_piece` samples where a pause allows: each cut is the middle of the longest pause
// whose middle lies in [start + min_piece, start + max_piece], else of the first pause after
// that; no cut leaves less than `min_piece` / 2 behind it.
std::vector<std::int64_t> cut_points(const std::vector<Pause>& pauses, std::int64_t length, std::int64_t min_piece,
                                     std::int64_t max_piece);

}  // namespace fapcast
