#pragma once
// Synthesis, paper sections 3.7-3.8 end to end: timed phones on the WAV timeline -> target
// phones on the voice's 60 fps grid (voice_frame_grid.hpp) -> Viterbi unit search
// (unit_search.hpp) -> warped, cross-faded, smoothed PCA frames (unit_concatenation.hpp), with the
// parametric tongue (tongue.hpp) on the same frames. The jaw travels in the PCA frames (the chin
// feature point 2.1 is on the mesh); codec turns both into FAPs.
#include "fapcast/core/input_error.hpp"
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/synthesis/jaw_guide.hpp"
#include "fapcast/synthesis/jaw_level.hpp"
#include "fapcast/synthesis/unit_concatenation.hpp"
#include "fapcast/select/unit_search.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <span>
#include <string>

namespace fapcast {

// Where a viseme class the voice never recorded borrows its units: up to three classes of the
// nearest visible shape, tried in order (spec/synthesis.md, "Phones the voice cannot cover").
struct VisemeFallback {
  VisemeClass viseme;
  std::array<VisemeClass, 3> substitutes;
};
std::span<const VisemeFallback, kVisemeClassCount> viseme_fallbacks();

// The class the search uses for `v` on `graph`: v itself when the graph has a state of it, else
// the first substitute that it has. Throws InputError (source "voice", rule
// "viseme-not-covered") naming the class and its substitutes when none is covered.
VisemeClass covered_viseme(const PhoneGraph& graph, VisemeClass v);

// Everything that shapes a synthesised track; the default value is what fapcast ships (the CLI's
// defaults are these members' defaults, so `eval synth` scores what `say` and `animate` make).
struct SynthesisOptions {
  SearchOptions search;  // beta, max_active, the duration, context and jaw terms
  ConcatenationOptions concatenation;  // where units hand over, cross-fade, smoothing, hold weight
  // The jaw term's wanted opening (jaw_guide.hpp) is low-passed at this frequency: about the rate
  // of syllables in speech (4-5 per second), so that a phone shares its neighbours' jaw. The jaw's
  // level takes the same cut-off: what is slower is the sentence's, what is faster the unit's.
  double jaw_cutoff_hz = 4.0;
  // How much of the frames' slow jaw moves to the wanted opening (jaw_level.hpp): 0 keeps the
  // units' own (the paper; the default), 1 gives the guide's (spec/synthesis.md, "The jaw's
  // level", for what it gains on real speech and costs on SYNTHETIC speech).
  double jaw_level = 0.0;
};

struct SynthesizedTrack {
  TargetTimeline timeline;     // the target phones on the 60 fps grid (before substitution)
  // k columns, one row per voice frame 0..timeline.frame_count()-1; row n is shown from sample
  // frame_to_sample(n, kVoiceFrameRate, timeline.sample_rate): the first frame is at sample 0.
  Eigen::MatrixXf pca_frames;
  Eigen::MatrixXf tongue;      // frames x 5: FAP 43..47 values (tongue.hpp)
  SearchResult search;         // states, units, cost, active states per phone
  std::size_t substituted = 0; // target phones whose class the voice lacked (covered_viseme)
  bool jaw_levelled = false;   // level_jaw moved the frames (jaw_level > 0, a guide with a jaw move)
};

// The voice's jaw guide when the options weigh the jaw term (search.jaw_weight > 0) or level the
// jaw (jaw_level > 0) on a voice with a chin (FP 2.1), else none: what the synthesize() calls
// below take as `jaw_guide`. Throws InputError as make_jaw_guide.
std::optional<JawGuide> jaw_guide_for(const Voice& voice, const SynthesisOptions& options);

// Synthesises the animation of `phones` (sample positions at `sample_rate`, see
// place_on_voice_grid for the rules and `end_sample`) on a voice: `graph` indexes the rows of
// `frame_coefficients` (corpus frames x k PCA coefficients, 60 fps). Throws InputError for
// phones breaking the rules or classes the voice cannot cover; an empty phone list gives an
// empty track. With the jaw term weighed, `jaw_guide` must be the voice's (jaw_guide_for), else
// std::invalid_argument; without a guide the jaw is not levelled (a voice without a chin).
SynthesizedTrack synthesize(const PhoneGraph& graph, const PcaFrames& frame_coefficients,
                            std::span<const TimedPhone> phones, SampleRate sample_rate,
                            std::int64_t end_sample = 0, const SynthesisOptions& options = {},
                            const std::string& source = "phones", const JawGuide* jaw_guide = nullptr);

// The same on a voice, with the voice's jaw guide when the options need it (jaw_guide_for): what
// `say` and `animate` make. Callers that synthesise many times keep the guide and call the above.
SynthesizedTrack synthesize(const Voice& voice, std::span<const TimedPhone> phones, SampleRate sample_rate,
                            std::int64_t end_sample = 0, const SynthesisOptions& options = {},
                            const std::string& source = "phones");

// The same for target phones already on the voice grid (place_on_voice_grid's rules). They
// need not start at frame 0: the search, the concatenation and the tongue see only the phones'
// classes, lengths and frames relative to each other (the pieces of a long text, spec/synthesis.md).
SynthesizedTrack synthesize(const PhoneGraph& graph, const PcaFrames& frame_coefficients,
                            TargetTimeline timeline, const SynthesisOptions& options = {},
                            const JawGuide* jaw_guide = nullptr);

}  // namespace fapcast
