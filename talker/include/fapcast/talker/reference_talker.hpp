#pragma once
// The reference talker (spec/talker.md): records a SYNTHETIC visual-speech
// corpus in the formats a capture studio delivers (spec/corpus.md): per utterance a C3D of the
// markers of spec/markers.tsv at 60 fps, the espeak-ng WAV, and a TextGrid with phone and word
// tiers; one manifest.json. Speech is real TTS (espeak-ng); the face is ICT-FaceKit with an
// identity mix (the "actor", not the generic target face); articulation follows Cohen-Massaro
// dominance functions (spec/talker.md); capture adds head motion, 0.2 mm marker noise and
// dropped markers. Seeded and reproducible.
#include "fapcast/corpus/alignment.hpp"
#include "fapcast/face/face_model.hpp"
#include "fapcast/corpus/marker_frames.hpp"
#include "fapcast/core/wav_file.hpp"
#include "fapcast/core/portable_random.hpp"
#include "fapcast/corpus/recording_script.hpp"
#include "fapcast/frontend/text_frontend.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fapcast {

// One recorded utterance: what the studio delivers, and the ground truth it came from.
struct ReferenceTake {
  std::string id;        // "utt0001"
  std::string text;      // the script item (a word, or a nonsense item's ARPAbet spelling)
  Audio audio;       // espeak-ng's audio
  Speech speech;         // phones and words on the audio's sample timeline
  Alignment alignment;   // phones and words tiers, marked SYNTHETIC
  MarkerFrames<Centimetres> clean;    // ground truth: the face's markers with no head motion, noise or drops
  MarkerFrames<Centimetres> captured; // what the capture delivers: head motion, noise, dropped markers
  float effort = 1.0f;   // articulation effort drawn for this utterance
};

// The actor's face: the generic ICT face plus an identity mix drawn from `seed`.
FaceModel reference_actor(const FaceModel& generic, std::uint64_t seed);

// Records one utterance of `item` on `actor`; draws its variation and imperfections from `random`.
ReferenceTake record_take(const ScriptItem& item, std::string id, const FaceModel& actor,
                          PortableRandom& random);

// The TextGrid tiers of a take: "phones" (ARPAbet, "sil" for silence), "words" (empty gaps),
// marked synthetic (alignment.hpp, mark_synthetic).
Alignment take_alignment(const Speech& speech);

struct ReferenceCorpusOptions {
  std::size_t count = 0;   // record the first `count` script items; 0 = all
  std::uint64_t seed = 1;  // the actor, every variation and every imperfection
  ScriptOptions script;
};

// Where a recorded file goes: `name` relative to the corpus directory, its bytes.
using CorpusFileSink = std::function<void(const std::string& name, std::string_view bytes)>;

struct ReferenceCorpusSummary {
  std::size_t utterances = 0;
  std::int64_t marker_frames = 0;  // at 60 fps
  double audio_seconds = 0.0;
  std::uint64_t bytes = 0;         // written through the sink, WAVs included
  std::size_t dropped_runs = 0;
  // Divisemes (recording_script.hpp) in the phones espeak-ng said, over all takes; and those the
  // recorded items' script phones have but the takes do not (espeak-ng read an item otherwise).
  std::size_t divisemes_recorded = 0;
  std::vector<std::uint32_t> divisemes_not_said;
};

// Records the corpus of `script` into `directory`: C3D, TextGrid and manifest.json through
// `sink` (the caller writes them, atomically), WAVs with write_wav. `progress(done, total)` is
// called after each utterance when set.
ReferenceCorpusSummary record_reference_corpus(
    const RecordingScript& script, const std::filesystem::path& directory,
    const ReferenceCorpusOptions& options, const CorpusFileSink& sink,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace fapcast
