#pragma once
// Retargeting fidelity (Ma et al. 2006, section 4.1): the lip measures of the source markers
// against those of the target face the voice's RBF map makes of them, over a corpus; also after
// the voice's PCA compression (what synthesis actually plays back).
#include <filesystem>
#include <functional>

#include "fapcast/core/input_error.hpp"
#include "fapcast/eval/lip_measures.hpp"
#include "fapcast/voice/voice.hpp"

namespace fapcast {

struct RetargetEvaluation {
  LipAgreement retargeted;  // source markers vs the RBF map's target face
  LipAgreement compressed;  // source markers vs the same face rebuilt from k PCA coefficients
  std::size_t utterances = 0;
  std::int64_t frames = 0;
};

// Reads every take of the corpus in `corpus_dir` (voice_corpus.hpp), stabilises it against the
// voice's rigid reference, and compares the curves. Throws InputError for a bad corpus, and
// InputError "voice-feature-points" when the voice lacks a lip point (8.1-8.4, H.temple_l/r).
RetargetEvaluation evaluate_retargeting(const Voice& voice, const std::filesystem::path& corpus_dir,
                                        const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace fapcast
