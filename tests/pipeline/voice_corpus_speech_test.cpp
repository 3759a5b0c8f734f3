// A corpus take with its speech (.wav) and transcript (.txt) but no alignment: the voice build's
// reader aligns it with the forced aligner (recognise/). Checked against the same SYNTHETIC takes
// read through the reference talker's own TextGrids, which hold the true phone timing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "fapcast/builder/voice_corpus.hpp"
#include "fapcast/core/file_io.hpp"
#include "fapcast/phonetics/viseme.hpp"
#include "fapcast/talker/reference_talker.hpp"

namespace fapcast {
namespace {

namespace fs = std::filesystem;

const char* const kSentences[] = {"the boy showed his father a good moon", "we see five red shoes"};

// The class of the phone at each frame of a take.
std::vector<VisemeClass> frame_classes(const CorpusTake& take) {
  std::vector<VisemeClass> out;
  for (std::size_t i = 0; i < take.phones.size(); ++i) {
    if (out.size() < take.spans[i].first) out.resize(take.spans[i].first, search_viseme(Phone::SIL));
    out.insert(out.end(), take.spans[i].count, search_viseme(take.phones[i]));
  }
  return out;
}

TEST(VoiceCorpusSpeech, TakesWithATranscriptButNoAlignmentAreAligned) {
  const fs::path dir = fs::temp_directory_path() / ("fapcast_corpus_speech_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  RecordingScript script;
  for (const char* s : kSentences) script.items.push_back({ScriptSection::kCommonWord, s, {}, "", 0.0});
  (void)record_reference_corpus(script, dir, {.count = 0, .seed = 3, .script = {}},
                                [&](const std::string& name, std::string_view bytes) { write_file_atomically(dir / name, bytes); });
  // the truth, from the manifest's TextGrids
  const CorpusListing truth = list_corpus(dir);
  ASSERT_EQ(truth.utterances.size(), 2u);
  std::vector<CorpusTake> expected;
  for (std::size_t i = 0; i < truth.utterances.size(); ++i) expected.push_back(read_corpus_take(truth, i));
  // the same takes as a plain directory: markers, WAV and transcript; no manifest, no TextGrid
  fs::remove(dir / "manifest.json");
  for (std::size_t i = 0; i < truth.utterances.size(); ++i) {
    const CorpusUtterance& u = truth.utterances[i];
    fs::remove(u.alignment);
    fs::path txt = u.markers;
    txt.replace_extension(".txt");
    write_file_atomically(txt, std::string(kSentences[i]) + "\n");
  }
  const CorpusListing listing = list_corpus(dir);
  ASSERT_EQ(listing.utterances.size(), 2u);
  for (std::size_t i = 0; i < listing.utterances.size(); ++i) {
    const CorpusUtterance& u = listing.utterances[i];
    SCOPED_TRACE(u.id);
    EXPECT_TRUE(u.alignment.empty());
    EXPECT_EQ(u.speech.extension(), ".wav");
    EXPECT_EQ(u.transcript.extension(), ".txt");
    const CorpusTake found = read_corpus_take(listing, i);
    EXPECT_EQ(found.markers.positions.cols(), expected[i].markers.positions.cols());
    const auto a = frame_classes(found), b = frame_classes(expected[i]);
    std::size_t same = 0, frames = std::min(a.size(), b.size());
    for (std::size_t f = 0; f < frames; ++f) same += a[f] == b[f];
    std::printf("%s: %zu phones found, %zu true; %zu of %zu frames in the true viseme class\n", u.id.c_str(),
                found.phones.size(), expected[i].phones.size(), same, frames);
    EXPECT_GE(frames, 60u);
    EXPECT_GE(static_cast<double>(same), 0.75 * static_cast<double>(frames));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fapcast
