#include "fba_standard_planes.hpp"

#include <vector>

namespace fapcast::detail {
namespace {
constexpr int kWidenAttempts = 8;  // other codings tried before the reference reading's is kept
}  // namespace

void StandardPlanes::start_code(std::uint32_t code) {
  out_.stuff_to_start_code();
  out_.start_code(code);
  carry_ = 0;
  restart_ = false;
}

void StandardPlanes::intra(const FapFrame& frame, const StandardIntraHeader& planned, bool start_code_follows) {
  const auto ranges = state_.ranges;
  const int blend = state_.blend_levels;
  const auto restore = [&] {
    state_.ranges = ranges;  // the rest of the state the next attempt sets again
    state_.blend_levels = blend;
  };
  if (write(frame, &planned, start_code_follows, true)) {
    ++intra_planes_;
    return;
  }
  // Other codings of the same frame, each with one range field widened by one: the header's last
  // field (it ends where the first segment starts), then the I fields of the first FAPs (their
  // model sizes decide the low-level segment's first bits). I fields not sent are sent, sized to
  // the frame.
  StandardIntraHeader header = planned;
  const auto sized = intra_range_fields(intra_levels(frame, header.fap_quant), frame.mask, header.fap_quant);
  std::vector<std::pair<int, int>> candidates;  // (flag 0..3 = i_max, i_min, p_max, p_min; FAP)
  const bool set[4] = {header.flags.i_max, header.flags.i_min, header.flags.p_max, header.flags.p_min};
  for (int flag = 3; flag >= 0 && candidates.empty(); --flag)
    for (int n = kFapCount; n >= kFirstLowLevelFap && candidates.empty() && set[flag]; --n)
      if (frame.mask.test(n)) candidates.emplace_back(flag, n);
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
    if (frame.mask.test(n)) candidates.emplace_back(0, n), candidates.emplace_back(1, n);
  int attempts = 0;
  for (const auto& [flag, n] : candidates) {
    if (attempts >= kWidenAttempts) break;
    StandardIntraHeader trial = header;
    FbaRangeFields& f = trial.fields[static_cast<std::size_t>(n - 1)];
    if (flag == 0 && !trial.flags.i_max) {
      trial.flags.i_max = true;
      for (std::size_t i = 0; i < sized.size(); ++i) trial.fields[i].i_max = sized[i].i_max;
    }
    if (flag == 1 && !trial.flags.i_min) {
      trial.flags.i_min = true;
      for (std::size_t i = 0; i < sized.size(); ++i) trial.fields[i].i_min = sized[i].i_min;
    }
    std::uint8_t& field = flag == 0 ? f.i_max : flag == 1 ? f.i_min : flag == 2 ? f.p_max : f.p_min;
    if (field >= kMaxRangeField) continue;
    ++field;
    ++attempts;
    restore();
    if (write(frame, &trial, start_code_follows, true)) {
      ++intra_planes_;
      ++recoded_;
      return;
    }
  }
  // No coding of this frame reads alike everywhere (its FAP 1/2 fields alone can decide that):
  // the reference reading's coding, counted; a start code after it, so that only this frame is
  // lost to a reader that reads otherwise.
  restore();
  write(frame, &planned, start_code_follows, false);
  ++intra_planes_;
  ++not_alike_;
  restart_ = true;
}

bool StandardPlanes::predicted(const FapFrame& frame, bool start_code_follows) {
  if (!write(frame, nullptr, start_code_follows, true)) {
    ++recoded_;
    return false;
  }
  ++predicted_planes_;
  return true;
}

bool StandardPlanes::write(const FapFrame& frame, const StandardIntraHeader* header, bool start_code_follows, bool checked) {
  if (restart_) start_code(kFbaPlaneStartCode);
  const FbaBitWriter::Mark mark = out_.mark();
  PlaneUpdates updates;
  write_plane(state_, frame, header, nullptr, 0, out_, &updates);
  if (checked && !reads_alike(out_, mark, carry_, start_code_follows)) {
    out_.rollback(mark);
    return false;
  }
  carry_ = continuous_zero_run(out_, mark, carry_);
  keep_plane(state_, updates);
  return true;
}

}  // namespace fapcast::detail
