#pragma once
// The jaw's level in connected speech (spec/synthesis.md, "The jaw's level"). The voice's units
// are cut from takes of single words between rests, and each brings the slow jaw of its own take:
// in a sentence the jaw rises and falls over the syllables (closed through a reduced "was", open
// through "for us") at a level no word spoken alone gives. Levelling moves the synthesised frames'
// slow jaw, below the guide's cut-off, towards the jaw its phones want in context (the voice's own
// per-phone means, jaw_guide.hpp), along the jaw's own move: the mandible lowers, the lips keep
// their shape. The fast jaw of each unit (its consonants' closing and opening) stays as recorded.
#include "fapcast/synthesis/jaw_guide.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <Eigen/Core>

namespace fapcast {

// Adds to each row of `pca_frames` (frames of `timeline`, from its first phone's first frame)
// `strength` x (wanted - slow) x the guide's jaw move, where `wanted` is wanted_jaw_frames and
// `slow` the frames' own opening low-passed alike. strength 0 changes nothing, 1 gives the frames
// the guide's slow jaw. A guide without a jaw move (a voice lacking the lips' feature points)
// changes nothing. Throws std::invalid_argument for a strength outside [0, 1], frames whose
// count or width do not match the timeline and the guide.
void level_jaw(const JawGuide& guide, const TargetTimeline& timeline, Eigen::MatrixXf& pca_frames, double cutoff_hz,
               double strength);

}  // namespace fapcast
