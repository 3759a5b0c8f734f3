#pragma once
// The jaw the unit search is asked to follow (SearchOptions::jaw_weight, spec/search.md, "The jaw
// term"). The search's alphabet is the viseme class, which lumps phones of one lip shape whatever
// their jaw (AH with AA, S with T), and its join cost sees two frames each side of a join: nothing
// in it asks a unit to bring the jaw height its phones have in this sentence. The guide gives each
// state its recorded jaw opening and each target phone the opening it should have: the voice's own
// mean over the states of that phone, laid on the target's frames and smoothed as fast as a jaw
// moves, so that neighbouring phones share their openings as they do in speech.
#include <Eigen/Core>

#include "fapcast/phonetics/phone.hpp"
#include "fapcast/voice/voice.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <array>
#include <vector>

namespace fapcast {

struct JawGuide {
  // Jaw openings in units of the spread (standard deviation) of the speech states' openings about
  // their mean: the jaw term's weight is then the same for a small face and a large one.
  std::vector<float> state_opening;              // per graph state, its frames' mean
  std::array<float, kPhoneCount> phone_opening;  // per phone, the mean of its states' (0: no state)
  double spread_mm = 0.0;                        // the unit, in millimetres of chin travel
  // A PCA frame's opening in the same units is (chin_drop . c - centre) / spread, chin_drop the
  // chin's travel downwards (metres) per unit of each coefficient.
  std::vector<float> chin_drop;
  double centre_mm = 0.0;  // the speech states' mean opening
  // The jaw's own move (jaw_level.hpp): the coefficient change that lowers the jaw by one unit
  // with the lips' shape held; empty when the voice lacks the feature points it needs.
  std::vector<float> jaw_move;
};

// The opening is how far the chin (FP 2.1) lies below its place on the PCA mean face, along the
// face's up axis (the frames are stabilised on the head). Throws InputError (the voice file, rule
// "jaw-guide") for a voice without FP 2.1 or whose chin does not move across its speech states.
JawGuide make_jaw_guide(const Voice& voice);

// The opening of PCA frame `c` (k coefficients) in the guide's units.
double frame_opening(const JawGuide& guide, const Eigen::Ref<const Eigen::RowVectorXf>& c);

// The opening wanted on each frame of the timeline (from its first phone's first frame): each
// phone's mean laid on its frames, low-passed at `cutoff_hz` with zero phase (spec/search.md).
std::vector<double> wanted_jaw_frames(const JawGuide& guide, const TargetTimeline& timeline, double cutoff_hz);

// The opening wanted at each target phone: wanted_jaw_frames averaged over the phone's frames.
std::vector<float> wanted_jaw(const JawGuide& guide, const TargetTimeline& timeline, double cutoff_hz);

}  // namespace fapcast
