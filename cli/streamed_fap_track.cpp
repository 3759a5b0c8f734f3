#include "streamed_fap_track.hpp"

#include "fap_output.hpp"
#include "file_extension.hpp"

#include "fapcast/core/frame_rate.hpp"
#include "fapcast/synthesis/synthesis.hpp"
#include "fapcast/utterance/fap_track.hpp"
#include "fapcast/voice/voice_frame_grid.hpp"

#include <cmath>
#include <stdexcept>

namespace fapcast::cli {
namespace {

// Frame lines gathered before they go to the file: big enough for few writes, small to hold.
constexpr std::size_t kTextFlushBytes = std::size_t{1} << 20;

bool is_pause(const TimedPhone& p, std::int64_t min_samples) {
  return search_viseme(p.phone) == VisemeClass::kSilence && p.end_sample - p.start_sample >= min_samples;
}

}  // namespace

bool is_streamed_output(const SynthesisArgs& args) {
  return !args.output.empty() && is_animation_output(args.output) && !is_mesh_output(args.output) &&
         !is_rig_output(args.output, args.rig) && args.rig.vmc.empty();
}

StreamedFapTrack::StreamedFapTrack(const SynthesisArgs& args, SampleRate sample_rate, std::string source,
                                   std::string name)
    : args_(args),
      sample_rate_(sample_rate),
      source_(std::move(source)),
      voice_(open_synthesis_voice(args)),
      jaw_guide_(jaw_guide_for(voice_, args.options)),
      speech_(speech_basis(voice_, args.expression)),
      basis_(face_basis(speech_, voice_, synthesis_voice_name(args))),
      animation_(animation_options(args, std::move(name))),
      rate_(animation_.rate),
      resampler_(kVoiceFrameRate, rate_, ResampleMode::kLinear,
                 [this](std::int64_t j, const FapFrame& frame) { take_frame(j, frame); }),
      piece_samples_(static_cast<std::int64_t>(std::llround(args.piece_seconds * sample_rate.hz))) {
  out_.emplace(args.output);
  if (lower_extension(args.output) == ".fap") {
    try {
      fap_text_.emplace(rate_, fap_write_options(args.player));
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(args.output + ": " + e.what());
    }
    body_.emplace(args.output);
  } else {
    held_.name = animation_.name;
    held_.rate = rate_;
  }
}

StreamedFapTrack::~StreamedFapTrack() = default;

void StreamedFapTrack::add(std::vector<TimedPhone>& phones) {
  if (piece_samples_ <= 0 || phones.empty()) return;
  const auto min_pause = static_cast<std::int64_t>(std::llround(kPieceCutPauseSeconds * sample_rate_.hz));
  // The last phone may still grow (a silence continued by the next chunk): never a cut.
  for (std::size_t c = 1; c + 1 < phones.size(); ++c) {
    if (!is_pause(phones[c], min_pause) || phones[c].end_sample - phones.front().start_sample < piece_samples_)
      continue;
    synthesize_piece({phones.data(), c + 1}, 0, false);
    phones.erase(phones.begin(), phones.begin() + static_cast<std::ptrdiff_t>(c));  // keep the pause
    first_phone_ += c;
    c = 0;
  }
}

void StreamedFapTrack::finish(std::vector<TimedPhone>& phones, std::int64_t audio_samples) {
  audio_samples_ = audio_samples;
  shown_ = frames_shown(audio_samples, rate_, sample_rate_);
  synthesize_piece(phones, audio_samples, true);
  phones.clear();
  resampler_.finish();
  const FapTextWriteOptions fap = fap_write_options(args_.player);
  if (fap_text_) {
    // The header (its counts known only now), the lines flushed so far, copied by the kernel,
    // then the ones still held.
    out_->write(fap_text_->header(animation_.name));
    out_->append_contents_of(*body_);
    out_->write(pending_text_);
    pending_text_.clear();
    pending_text_.shrink_to_fit();
    body_.reset();  // never committed: removed
    notes_ = fap_text_player_notes(fap_text_->stats(), fap);
  } else {
    TrackFileBytes bytes = animation_bytes(args_.output, held_, fap, sample_rate_, basis_.neutral);
    held_.frames.clear();
    out_->write(bytes.bytes);
    notes_ = std::move(bytes.notes);
  }
  print_notes(args_.output, notes_);
}

void StreamedFapTrack::synthesize_piece(std::span<const TimedPhone> phones, std::int64_t end_sample, bool last) {
  const auto start = std::chrono::steady_clock::now();
  TargetTimeline timeline = place_on_voice_grid(phones, sample_rate_, end_sample, source_, first_phone_);
  // A piece after the first starts in the pause the one before ended in: its frames count from
  // there (the silence place_on_voice_grid fills before it is the pieces before).
  std::int64_t origin = 0;
  if (pieces_ > 0) {
    origin = first_frame_at(phones.front().start_sample, kVoiceFrameRate, sample_rate_);
    if (origin > 0 && !timeline.phones.empty() && timeline.phones.front().end_frame == origin) {
      timeline.phones.erase(timeline.phones.begin());
      timeline.phone_of.erase(timeline.phone_of.begin());
      --timeline.gaps_filled;
    }
    for (TargetPhone& t : timeline.phones) {
      t.first_frame -= origin;
      t.end_frame -= origin;
    }
  }
  const std::size_t targets = timeline.phones.size();
  // Not the last piece: it ends in the middle of its last target, the pause.
  const std::int64_t end_frame =
      last || targets == 0 ? timeline.frame_count()
                           : (timeline.phones.back().first_frame + timeline.phones.back().end_frame) / 2;
  phones_ += targets - (pieces_ > 0 && targets > 0 ? 1 : 0);  // the pause it starts in was counted
  dropped_ += timeline.dropped;
  SynthesizedTrack track = synthesize(voice_.graph(), voice_.frame_coefficients(), std::move(timeline), args_.options,
                                      jaw_guide_ ? &*jaw_guide_ : nullptr);
  units_ += track.search.units.size();
  substituted_ += track.substituted;
  ++pieces_;
  track.pca_frames = speech_weights(track.pca_frames, speech_);
  const FapSequence frames = voice_rate_faps(track, basis_, animation_);
  synthesis_time_ += std::chrono::steady_clock::now() - start;
  for (std::int64_t n = kept_from_ - origin; n < end_frame; ++n) resampler_.push(frames.frames[static_cast<std::size_t>(n)]);
  kept_from_ = origin + end_frame;
}

void StreamedFapTrack::take_frame(std::int64_t j, const FapFrame& frame) {
  if (shown_ >= 0 && j >= shown_) return;  // shown after the sound has ended (fap_track's rule)
  ++frames_written_;
  if (!fap_text_) {
    held_.frames.push_back(frame);
    return;
  }
  try {
    fap_text_->append(pending_text_, frame);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(args_.output + ": " + e.what());
  }
  if (pending_text_.size() >= kTextFlushBytes) {
    body_->write(pending_text_);
    pending_text_.clear();
  }
}

std::string StreamedFapTrack::summary(std::string_view outputs) const {
  SynthesisReport report;
  report.frames = static_cast<std::size_t>(frames_written_);
  report.fps = args_.fps;
  report.audio_seconds = static_cast<double>(audio_samples_) / static_cast<double>(sample_rate_.hz);
  report.phones = phones_;
  report.units = units_;
  report.pieces = pieces_;
  report.synthesis_ms = std::chrono::duration<double>(synthesis_time_).count() * 1000.0;
  report.substituted = substituted_;
  report.dropped = dropped_;
  return synthesis_summary(args_, report, outputs);
}

}  // namespace fapcast::cli
