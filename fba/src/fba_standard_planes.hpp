#pragma once
// Standard planes as fapcast's encoders write them: each kept only when every standard decoder
// reads it alike (either stuffing reading, and the published decoder's fixed give-back: spec/fba.md
// §2). A P plane that fails is given back for the caller to code as an intra plane instead; an
// intra plane that fails is coded again with a range field widened, and when no such coding
// reads alike (rare: FAP 1/2 fields alone can decide it), with the reference reading's coding,
// counted. Internal to the codec.
#include "fba_plane.hpp"

#include <cstdint>

namespace fapcast::detail {

class StandardPlanes {
 public:
  StandardPlanes(FbaBitWriter& out, FbaCodingState& state, std::uint64_t& intra_planes,
                 std::uint64_t& predicted_planes, std::uint64_t& recoded, std::uint64_t& not_alike)
      : out_(out), state_(state), intra_planes_(intra_planes), predicted_planes_(predicted_planes), recoded_(recoded),
        not_alike_(not_alike) {}
  // next_start_code() stuffing and a start code: a continuous reader's count starts again.
  void start_code(std::uint32_t code);
  // `start_code_follows`: the plane is followed by stuffing and a start code, else by a P plane.
  void intra(const FapFrame& frame, const StandardIntraHeader& header, bool start_code_follows);
  // False: the plane was given back (not written); the caller codes the frame as an intra plane.
  bool predicted(const FapFrame& frame, bool start_code_follows);

 private:
  bool write(const FapFrame& frame, const StandardIntraHeader* header, bool start_code_follows, bool checked);
  FbaBitWriter& out_;
  FbaCodingState& state_;
  std::uint64_t &intra_planes_, &predicted_planes_, &recoded_, &not_alike_;
  int carry_ = 0;         // zeros a continuous reader counts into the next plane
  bool restart_ = false;  // a start code before the next plane (after one that reads otherwise)
};

}  // namespace fapcast::detail
