#pragma once
// One pocketsphinx decoder with the US English acoustic model Debian ships (packages
// pocketsphinx-en-us and libpocketsphinx3, version 0.8+5prealpha), through its public C API:
// it decodes 16 kHz mono speech against a grammar (states joined by dictionary words, with
// optional silence and noise loops) and returns the segments
// of the best path. Not thread-safe: one decoder per thread (spec/recognise.md, "Decoder").
// A private header of fapcast::recognise: nothing outside the library sees pocketsphinx.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace fapcast {

// The model's sampling rate: speech is resampled to it before decoding (resample.hpp).
inline constexpr std::int64_t kDecoderSampleRateHz = 16000;

struct DecoderSettings {
  // Feature frames per second: 100 is the rate the model was trained at; 200 (5 ms frames) halves
  // every HMM's three-frame minimum duration. 100 or 200.
  int frames_per_second = 100;
  // Gaussian scores are computed every `gmm_every`-th frame and reused in between (1 or 2).
  int gmm_every = 1;
  // Viterbi beams (pocketsphinx -beam, -pbeam, -wbeam), as probabilities relative to the best path.
  double beam = 1e-60;
  double phone_beam = 1e-60;
  double word_beam = 1e-40;
};

// A grammar over dictionary words: arcs between states 0..states-1, from `start` to `final`.
// An arc with an empty word is a null arc (no audio). Silence and noise may repeat at every
// state listed in `pause_states`.
struct Grammar {
  struct Arc {
    int from = 0;
    int to = 0;
    std::string word;          // a dictionary word ("was", "was(2)", or one added with add_word)
    double probability = 1.0;  // 0 < p <= 1
  };
  int states = 1;
  int start = 0;
  int final = 0;
  std::vector<Arc> arcs;
  std::vector<int> pause_states;
  double silence_probability = 0.1;
  double noise_probability = 0.02;
};

// One segment of the best path, in decoder frames [start_frame, end_frame).
struct DecodedSegment {
  std::string word;        // dictionary word, "<sil>", "<s>", "</s>", "[NOISE]", "+NSN+" ...
  int start_frame = 0;
  int end_frame = 0;
  double score_per_frame = 0;  // acoustic log-likelihood per frame relative to each frame's best
                           // computed senone, natural log (<= 0 for the best path's own senones)
};

class Decoder {
 public:
  // Opens the model; throws std::runtime_error naming the missing file or package.
  explicit Decoder(const DecoderSettings& settings = {});
  ~Decoder();
  Decoder(const Decoder&) = delete;
  Decoder& operator=(const Decoder&) = delete;

  const DecoderSettings& settings() const;

  // The dictionary's pronunciations of `word` (lower case): "word", "word(2)" ... as CMUdict
  // phone strings ("W AA Z"); empty when the dictionary lacks it.
  std::vector<std::string> pronunciations(const std::string& word) const;
  bool has_word(const std::string& word) const;
  // Adds each (word, pronunciation) pair not yet present; a pronunciation is CMUdict phones
  // separated by spaces ("G R EH G S AH N").
  void add_words(const std::vector<std::pair<std::string, std::string>>& words);

  // The best path through `grammar` over `samples` (16 kHz mono); nullopt when no path reaches
  // its final state.
  std::optional<std::vector<DecodedSegment>> decode(const Grammar& grammar,
                                                    std::span<const std::int16_t> samples);

  // The words of `samples` (16 kHz mono) by recognition with the model's US English word 3-gram
  // (en-us.lm.bin, loaded on first use) and fast beams: 1e-40 / 1e-40 / 1e-25, no flat-lexicon
  // pass, at most 1500 HMMs per frame, phone lookahead 10 frames (spec/recognise.md,
  // "Recognition"). Words, silences and fillers in order; empty when nothing was found.
  std::vector<DecodedSegment> recognise_words(std::span<const std::int16_t> samples);

  // The 16 kHz sample where frame `frame`'s segment begins: halfway between the centres of
  // frames frame-1 and frame (each frame's 410-sample window starts frame * shift samples in).
  std::int64_t frame_start_sample(int frame) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fapcast
