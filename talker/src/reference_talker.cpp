#include "fapcast/talker/reference_talker.hpp"

#include "fapcast/corpus/c3d.hpp"
#include "fapcast/talker/capture_imperfections.hpp"
#include "fapcast/talker/coarticulation.hpp"
#include "fapcast/face/marker_map.hpp"
#include "fapcast/core/synthetic_label.hpp"
#include "fapcast/talker/rest_padding.hpp"
#include "fapcast/talker/talker_markers.hpp"
#include "fapcast/corpus/textgrid.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <stdexcept>

namespace fapcast {
namespace {

// Identity weights of the actor: far enough from the generic face that retargeting has work to
// do, within the range the ICT identity shapes were built for.
constexpr double kIdentityWeightLimit = 0.6;

double seconds(std::int64_t sample, int rate_hz) {
  return static_cast<double>(sample) / static_cast<double>(rate_hz);
}

// Appends [start, end) labelled `label` to an interval tier, filling any gap before it with an
// unlabelled interval (Praat tiers tile their span). Empty stretches are skipped.
void append_interval(LabelTier& tier, double start, double end, std::string label) {
  const double last = tier.intervals.empty() ? tier.start_s : tier.intervals.back().end_s;
  if (start > last) tier.intervals.push_back({last, start, ""});
  start = std::max(start, last);
  if (end > start) tier.intervals.push_back({start, end, std::move(label)});
}

// Fills the tier's tail after its last interval.
void close_tier(LabelTier& tier) {
  const double last = tier.intervals.empty() ? tier.start_s : tier.intervals.back().end_s;
  if (tier.end_s > last) tier.intervals.push_back({last, tier.end_s, ""});
}

std::string phone_label(Phone p) { return p == Phone::SIL ? "sil" : std::string(arpabet(p)); }

PhoneTimeline timeline_of(const Speech& speech) {
  PhoneTimeline timeline;
  timeline.sample_rate = speech.audio.sample_rate;
  for (const auto& p : speech.phones)
    if (p.end_sample > p.start_sample) timeline.phones.push_back(p);
  return timeline;
}

}  // namespace

FaceModel reference_actor(const FaceModel& generic, std::uint64_t seed) {
  PortableRandom random(seed ^ 0xAC702ull);
  std::vector<float> weights(generic.identities.size());
  for (auto& w : weights) w = static_cast<float>(random.uniform(-kIdentityWeightLimit, kIdentityWeightLimit));
  return make_actor(generic, weights);
}

Alignment take_alignment(const Speech& speech) {
  const auto rate = static_cast<int>(speech.audio.sample_rate.hz);
  const double end = seconds(static_cast<std::int64_t>(speech.audio.samples.size()), rate);
  Alignment a{0.0, end, {}};
  LabelTier phones{"phones", TierKind::intervals, 0.0, end, {}, {}};
  for (const auto& p : speech.phones)
    append_interval(phones, seconds(p.start_sample, rate), std::min(end, seconds(p.end_sample, rate)), phone_label(p.phone));
  close_tier(phones);
  LabelTier words{"words", TierKind::intervals, 0.0, end, {}, {}};
  for (const auto& w : speech.words)
    append_interval(words, seconds(w.start_sample, rate), std::min(end, seconds(w.end_sample, rate)), w.text);
  close_tier(words);
  a.tiers = {std::move(phones), std::move(words)};
  mark_synthetic(a);
  return a;
}

ReferenceTake record_take(const ScriptItem& item, std::string id, const FaceModel& actor,
                          PortableRandom& random) {
  ReferenceTake take;
  take.id = std::move(id);
  take.text = item.text;
  const UtteranceVariation variation = draw_utterance_variation(random);
  take.effort = variation.effort;
  const bool nonsense = item.section == ScriptSection::kNonsense;
  Speech spoken = speak(nonsense ? item.espeak_phonemes : item.text, SpeakOptions{.phoneme_input = nonsense, .rate_factor = variation.rate_factor});
  if (spoken.phones.empty())
    throw std::runtime_error("reference talker: espeak-ng said nothing for \"" + item.text + "\"");
  take.speech = with_rest(std::move(spoken), RestPadding{});
  take.audio = take.speech.audio;
  take.alignment = take_alignment(take.speech);
  take.clean = talker_markers(actor, timeline_of(take.speech), {60, variation.effort});
  take.captured = capture_take(take.clean, random).frames;
  return take;
}

ReferenceCorpusSummary record_reference_corpus(
    const RecordingScript& script, const std::filesystem::path& directory,
    const ReferenceCorpusOptions& options, const CorpusFileSink& sink,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  std::filesystem::create_directories(directory);
  const FaceModel actor = reference_actor(ict_face_model(), options.seed);
  PortableRandom master(options.seed);
  const std::size_t total =
      options.count == 0 ? script.items.size() : std::min(options.count, script.items.size());

  nlohmann::json manifest{{"format", "fapcast-corpus"},
                          {"version", 1},
                          {"synthetic", true},
                          {"provenance", kSyntheticLabel},
                          {"seed", options.seed},
                          {"frame_rate_hz", 60},
                          {"units", "mm"}};
  nlohmann::json marker_map = nlohmann::json::object();
  for (const auto& site : marker_sites())
    marker_map[std::string(site.label)] = site.role == MarkerRole::rigid ? std::string("rigid") : std::string(site.label);
  manifest["marker_map"] = marker_map;
  nlohmann::json utterances = nlohmann::json::array();

  ReferenceCorpusSummary summary;
  std::vector<bool> scripted(kDivisemeCount, false), said(kDivisemeCount, false);
  auto write = [&](const std::string& name, std::string_view bytes) {
    sink(name, bytes);
    summary.bytes += bytes.size();
  };
  for (std::size_t i = 0; i < total; ++i) {
    char id[32];
    std::snprintf(id, sizeof id, "utt%04zu", i + 1);
    PortableRandom random = master.split();  // one stream per take: takes are independent
    const ScriptItem& item = script.items[i];
    ReferenceTake take;
    try {
      take = record_take(item, id, actor, random);
    } catch (...) {
      std::throw_with_nested(std::runtime_error(std::string("recording ") + id + " (\"" + item.text + "\")"));
    }
    const std::string stem = id;
    write_wav(directory / (stem + ".wav"), take.audio);
    summary.bytes += std::filesystem::file_size(directory / (stem + ".wav"));
    write(stem + ".c3d", write_c3d(to_millimetres(take.captured),
                                   {c3d_synthetic_parameter(),
                                    {"FAPCAST", "TEXT", item.text.substr(0, 255), "the script item spoken"}}));
    write(stem + ".TextGrid", write_textgrid(take.alignment));
    utterances.push_back({{"id", stem},
                          {"text", item.text},
                          {"section", item.section == ScriptSection::kCommonWord   ? "common-word"
                                      : item.section == ScriptSection::kSyllableWord ? "syllable-word"
                                                                                      : "nonsense"},
                          {"files", {{"markers", stem + ".c3d"}, {"audio", stem + ".wav"}, {"alignment", stem + ".TextGrid"}}},
                          {"frame_rate_hz", 60},
                          {"sample_rate_hz", take.audio.sample_rate.hz},
                          {"effort", take.effort},
                          {"synthetic", true}});
    std::vector<Phone> spoken_phones;
    for (const TimedPhone& p : take.speech.phones) spoken_phones.push_back(p.phone);
    for (std::uint32_t d : divisemes_of(phones_of(item.syllables))) scripted[d] = true;
    for (std::uint32_t d : divisemes_of(spoken_phones)) said[d] = true;
    ++summary.utterances;
    summary.marker_frames += take.captured.frame_count();
    summary.audio_seconds += seconds(static_cast<std::int64_t>(take.audio.samples.size()), static_cast<int>(take.audio.sample_rate.hz));
    if (progress) progress(i + 1, total);
  }
  for (std::uint32_t d = 0; d < kDivisemeCount; ++d) {
    if (said[d]) ++summary.divisemes_recorded;
    else if (scripted[d]) summary.divisemes_not_said.push_back(d);
  }
  manifest["utterances"] = std::move(utterances);
  write("manifest.json", manifest.dump(2) + "\n");
  return summary;
}

}  // namespace fapcast
