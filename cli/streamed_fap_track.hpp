#pragma once
// `say`'s FAP track made piece by piece as the speech comes (spec/synthesis.md, "Long texts"):
// the phone stream is cut in long pauses, each piece is searched, concatenated and turned into
// FAP frames on its own, and its frames go to the output file as they come. Memory is bounded
// by the longest piece, not the text.
#include "animation.hpp"
#include "synthesis_cli.hpp"

#include "fapcast/codec/fap_text.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/transport/track_resample.hpp"
#include "fapcast/utterance/voice_face.hpp"
#include "fapcast/voice/voice.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast::cli {

// A pause where a piece may end: a silence of at least this long (the face is at rest in it).
inline constexpr double kPieceCutPauseSeconds = 0.25;

// Whether `path` is an output the pieces can be written to: a FAP track (.fap, .fba, .json,
// .bvh) without a rig. .fap is streamed to disk; .fba, .json and .bvh hold their frames until
// the end (their writers take the whole track: spec/synthesis.md, "Long texts").
bool is_streamed_output(const SynthesisArgs& args);

class StreamedFapTrack {
 public:
  // Opens the voice and the output's temporary files. args.piece_seconds: a piece ends at the
  // first pause of kPieceCutPauseSeconds after that much speech (0: one piece, the whole text).
  StreamedFapTrack(const SynthesisArgs& args, SampleRate sample_rate, std::string source, std::string name);
  ~StreamedFapTrack();
  StreamedFapTrack(const StreamedFapTrack&) = delete;
  StreamedFapTrack& operator=(const StreamedFapTrack&) = delete;

  // `phones`: the timed phones so far on the WAV timeline (the last one may still grow, as
  // append_timing merges silences). Synthesises every piece that ends before the last phone and
  // erases its phones from `phones` but the pause the next piece starts in.
  void add(std::vector<TimedPhone>& phones);
  // The last piece (`phones` to the audio's end, `audio_samples`), and the output written to
  // its temporary file; `commit` then renames it (with the WAV: commit_together).
  void finish(std::vector<TimedPhone>& phones, std::int64_t audio_samples);
  AtomicFile& output() { return *out_; }
  // The summary line `say` prints (synthesis_summary), with `outputs` (the cues' part).
  std::string summary(std::string_view outputs) const;

 private:
  void synthesize_piece(std::span<const TimedPhone> phones, std::int64_t end_sample, bool last);
  void take_frame(std::int64_t j, const FapFrame& frame);

  const SynthesisArgs& args_;
  SampleRate sample_rate_;
  std::string source_;
  Voice voice_;
  std::optional<JawGuide> jaw_guide_;  // with the jaw term on
  SpeechBasis speech_;
  FeaturePointBasis basis_;
  AnimationOptions animation_;
  FrameRate rate_;
  TrackResampler resampler_;
  std::int64_t piece_samples_;     // args.piece_seconds in samples (0: no cuts)
  std::int64_t kept_from_ = 0;     // the first voice frame the next piece gives (its cut)
  std::size_t first_phone_ = 0;    // the index in the whole text of the first phone not yet erased
  std::int64_t shown_ = -1;        // output frames shown (known at finish)
  std::optional<AtomicFile> out_;
  // .fap: the frames' lines go to `body_` as they come, the header and then the body to out_ at
  // the end (the header counts the frames).
  std::optional<FapTextFrameWriter> fap_text_;
  std::optional<AtomicFile> body_;
  std::string pending_text_;
  FapSequence held_;  // .fba, .json, .bvh: the frames until the end
  std::chrono::steady_clock::duration synthesis_time_{};
  std::size_t pieces_ = 0, phones_ = 0, units_ = 0, substituted_ = 0, dropped_ = 0;
  std::int64_t audio_samples_ = 0;
  std::int64_t frames_written_ = 0;
  std::vector<std::string> notes_;
};

}  // namespace fapcast::cli
