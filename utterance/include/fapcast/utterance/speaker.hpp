#pragma once
// A voice ready to speak, sentence after sentence, with one set of settings: the bases it needs
// (the PCA basis with the expression's direction, and its restriction to the feature points) are
// made once; each sentence then runs text -> espeak-ng speech and phones -> unit search and
// concatenation (synthesis) -> FAP frames at the output rate, and the PCA weights of the same
// frames (glTF morph weights of the voice's face). What `fapcast serve` runs per sentence.
#include "fapcast/codec/fap_frame.hpp"
#include "fapcast/codec/feature_point_basis.hpp"
#include "fapcast/core/audio.hpp"
#include "fapcast/frontend/text_frontend.hpp"
#include "fapcast/phonetics/timed_phone.hpp"
#include "fapcast/synthesis/speech_expression.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/voice/voice.hpp"

#include <Eigen/Core>

#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

struct SpeakerSettings {
  SpeakOptions speech;                        // espeak-ng: language, variant, SSML, rate
  SynthesisOptions synthesis;                 // the library's defaults: what `say` ships
  FrameRate rate{25, 1};                      // output frames per second
  std::optional<ExpressionBlend> expression;  // FAP 2, and the face's expression direction
  bool viseme = false;                        // FAP 1 in every frame
  std::string name = "fapcast";
};

struct SpokenSentence {
  Audio audio;                     // espeak-ng's own rate, mono 16-bit
  std::vector<TimedPhone> phones;  // on the audio's samples
  FapSequence faps;                // at the settings' rate: frame j shows at frame_to_sample(j)
  Eigen::MatrixXf weights;         // the same frames' k PCA coefficients (frames x k)
  std::chrono::nanoseconds speech_time{0};     // espeak-ng (the text front-end)
  std::chrono::nanoseconds animation_time{0};  // synthesis and FAPs after it
};

class Speaker {
 public:
  // Throws std::runtime_error when the voice's phone set is not this build's or a label is not a
  // feature point (naming `source`); std::invalid_argument when the expression does not fit the
  // voice's face. `voice` must outlive the speaker.
  Speaker(const Voice& voice, SpeakerSettings settings, const std::string& source);

  // Speaks one sentence (UTF-8, or SSML when settings().speech says so) in the settings'
  // language. Throws as fapcast::speak does (InputError for text breaking the front-end's
  // rules); white-space-only text gives an empty sentence (no audio, no frames).
  SpokenSentence speak(std::string_view text) const;

  const SpeakerSettings& settings() const { return settings_; }
  const SpeechBasis& basis() const { return basis_; }
  std::int64_t components() const { return basis_.pca_count(); }

 private:
  const Voice& voice_;
  std::optional<JawGuide> jaw_guide_;  // with the jaw term on
  SpeakerSettings settings_;
  SpeechBasis basis_;
  FeaturePointBasis face_;
  std::string source_;
};

// The rows of `frames` (one per frame at `from` fps, row 0 at time 0) at `to` fps: row j is
// interpolated linearly at time j / to (its position j * from / to in rows, exact rational),
// the last row held past the end; `count` rows.
Eigen::MatrixXf resample_rows(const Eigen::MatrixXf& frames, FrameRate from, FrameRate to, std::int64_t count);

}  // namespace fapcast
