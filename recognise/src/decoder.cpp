#include "decoder.hpp"

#include <pocketsphinx.h>
#include <sphinxbase/ckd_alloc.h>
#include <sphinxbase/err.h>
#include <sphinxbase/fsg_model.h>
#include <sphinxbase/glist.h>
#include <sphinxbase/logmath.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fapcast {

namespace {

// Debian's pocketsphinx-en-us.
constexpr const char* kModelDir = "/usr/share/pocketsphinx/model/en-us";

// 100 ms of silence on each side of the speech: an utterance that starts or ends inside a phone
// still leaves the search room to enter and leave its HMMs.
constexpr std::int64_t kPadSamples = kDecoderSampleRateHz / 10;
// The analysis window: 0.025625 s at 16 kHz (the model's feat.params).
constexpr std::int64_t kWindowSamples = 410;

std::string model_file(const char* name) {
  std::string path = std::string(kModelDir) + "/" + name;
  if (!std::filesystem::exists(path))
    throw std::runtime_error("pocketsphinx model file missing: " + path + " (Debian package pocketsphinx-en-us)");
  return path;
}

std::string decimal(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

struct Decoder::Impl {
  DecoderSettings settings;
  cmd_ln_t* config = nullptr;
  ps_decoder_t* ps = nullptr;
  double nats_per_unit = 0;  // one unit of a segment score (log base 1.0001, shifted 10 bits)
  std::int64_t shift = 160;  // samples per frame
  bool language_model = false;  // the "words" search (recognise_words) exists

  ~Impl() {
    if (ps) ps_free(ps);
    if (config) cmd_ln_free_r(config);
  }

  void run(std::span<const std::int16_t> samples) {
    std::vector<std::int16_t> padded(samples.size() + 2 * kPadSamples, 0);
    std::copy(samples.begin(), samples.end(), padded.begin() + kPadSamples);
    if (ps_start_utt(ps) < 0) throw std::logic_error("pocketsphinx: cannot start an utterance");
    // A decoder that refuses audio it was built for is a fault here, not in the recording.
    if (ps_process_raw(ps, padded.data(), padded.size(), FALSE, TRUE) < 0 || ps_end_utt(ps) < 0)
      throw std::logic_error("pocketsphinx: the decoder refused the audio");
  }

  std::optional<std::vector<DecodedSegment>> best_path() {
    std::int32_t score = 0;
    if (!ps_get_hyp(ps, &score)) return std::nullopt;
    std::vector<DecodedSegment> out;
    for (ps_seg_t* s = ps_seg_iter(ps); s; s = ps_seg_next(s)) {
      int sf = 0, ef = 0;
      ps_seg_frames(s, &sf, &ef);
      std::string word = ps_seg_word(s);
      if (word == "(NULL)" || ef < sf) continue;
      std::int32_t ascr = 0, lscr = 0, lback = 0;
      ps_seg_prob(s, &ascr, &lscr, &lback);
      out.push_back({word, sf, ef + 1, ascr * nats_per_unit / (ef - sf + 1)});
    }
    if (out.empty()) return std::nullopt;
    out.front().start_frame = 0;
    for (std::size_t i = 1; i < out.size(); ++i) out[i - 1].end_frame = out[i].start_frame;
    return out;
  }
};

Decoder::Decoder(const DecoderSettings& settings) : impl_(std::make_unique<Impl>()) {
  if (settings.frames_per_second != 100 && settings.frames_per_second != 200)
    throw std::invalid_argument("Decoder: frames_per_second must be 100 or 200");
  if (settings.gmm_every < 1 || settings.gmm_every > 2)
    throw std::invalid_argument("Decoder: gmm_every must be 1 or 2");
  impl_->settings = settings;
  impl_->shift = kDecoderSampleRateHz / settings.frames_per_second;
  const std::string hmm = model_file("en-us"), dict = model_file("cmudict-en-us.dict");
  const std::string frate = std::to_string(settings.frames_per_second), ds = std::to_string(settings.gmm_every);
  const std::string beam = decimal(settings.beam), pbeam = decimal(settings.phone_beam),
                    wbeam = decimal(settings.word_beam);
  impl_->config = cmd_ln_init(nullptr, ps_args(), TRUE, "-hmm", hmm.c_str(), "-dict", dict.c_str(),
                              "-frate", frate.c_str(), "-ds", ds.c_str(), "-beam", beam.c_str(),
                              "-pbeam", pbeam.c_str(), "-wbeam", wbeam.c_str(), "-remove_silence", "no",
                              "-dither", "yes", "-seed", "1", "-fsgusefiller", "no", "-fsgusealtpron", "no",
                              "-bestpath", "no", "-logfn", "/dev/null", nullptr);
  if (!impl_->config) throw std::logic_error("pocketsphinx: bad configuration");
  impl_->ps = ps_init(impl_->config);
  if (!impl_->ps) throw std::runtime_error("pocketsphinx: cannot open the model in " + hmm);
  impl_->nats_per_unit = std::log(logmath_get_base(ps_get_logmath(impl_->ps))) * (1 << 10);
}

std::vector<DecodedSegment> Decoder::recognise_words(std::span<const std::int16_t> samples) {
  if (!impl_->language_model) {
    // a search reads the configuration when it is created: the recognition's settings are set
    // for the 3-gram search alone, then the grammar searches' restored
    cmd_ln_t* c = impl_->config;
    cmd_ln_set_float_r(c, "-beam", 1e-40);
    cmd_ln_set_float_r(c, "-pbeam", 1e-40);
    cmd_ln_set_float_r(c, "-wbeam", 1e-25);
    const int fwdflat = cmd_ln_boolean_r(c, "-fwdflat");
    cmd_ln_set_boolean_r(c, "-fwdflat", FALSE);
    const long maxhmmpf = cmd_ln_int32_r(c, "-maxhmmpf"), pl_window = cmd_ln_int32_r(c, "-pl_window");
    cmd_ln_set_int32_r(c, "-maxhmmpf", 1500);
    cmd_ln_set_int32_r(c, "-pl_window", 10);
    const std::string lm = model_file("en-us.lm.bin");
    const int set = ps_set_lm_file(impl_->ps, "words", lm.c_str());
    cmd_ln_set_float_r(c, "-beam", impl_->settings.beam);
    cmd_ln_set_float_r(c, "-pbeam", impl_->settings.phone_beam);
    cmd_ln_set_float_r(c, "-wbeam", impl_->settings.word_beam);
    cmd_ln_set_int32_r(c, "-maxhmmpf", maxhmmpf);
    cmd_ln_set_int32_r(c, "-pl_window", pl_window);
    cmd_ln_set_boolean_r(c, "-fwdflat", fwdflat);
    if (set < 0) throw std::runtime_error("pocketsphinx: cannot read the language model " + lm);
    impl_->language_model = true;
  }
  ps_set_search(impl_->ps, "words");
  impl_->run(samples);
  return impl_->best_path().value_or(std::vector<DecodedSegment>{});
}

Decoder::~Decoder() = default;

const DecoderSettings& Decoder::settings() const { return impl_->settings; }

std::vector<std::string> Decoder::pronunciations(const std::string& word) const {
  std::vector<std::string> out;
  for (int k = 1; k < 10; ++k) {
    const std::string key = k == 1 ? word : word + "(" + std::to_string(k) + ")";
    char* p = ps_lookup_word(impl_->ps, key.c_str());
    if (!p) {
      if (k == 1) break;
      continue;
    }
    out.emplace_back(p);
    ckd_free(p);
  }
  return out;
}

bool Decoder::has_word(const std::string& word) const {
  char* p = ps_lookup_word(impl_->ps, word.c_str());
  if (!p) return false;
  ckd_free(p);
  return true;
}

void Decoder::add_words(const std::vector<std::pair<std::string, std::string>>& words) {
  std::vector<const std::pair<std::string, std::string>*> missing;
  for (const auto& w : words)
    if (!has_word(w.first)) missing.push_back(&w);
  for (std::size_t i = 0; i < missing.size(); ++i) {
    const auto& [word, phones] = *missing[i];
    // the search's lexicon is rebuilt once, after the last word
    if (ps_add_word(impl_->ps, word.c_str(), phones.c_str(), i + 1 == missing.size()) < 0)
      throw std::logic_error("pocketsphinx: cannot add the word '" + word + "' /" + phones + "/");
  }
}

std::optional<std::vector<DecodedSegment>> Decoder::decode(const Grammar& g, std::span<const std::int16_t> samples) {
  logmath_t* lmath = ps_get_logmath(impl_->ps);
  fsg_model_t* fsg = fsg_model_init("grammar", lmath, static_cast<float>(cmd_ln_float32_r(impl_->config, "-lw")), g.states);
  fsg->start_state = g.start;
  fsg->final_state = g.final;
  for (const auto& a : g.arcs) {
    const std::int32_t logp = logmath_log(lmath, a.probability);
    if (a.word.empty())
      fsg_model_null_trans_add(fsg, a.from, a.to, logp);
    else
      fsg_model_trans_add(fsg, a.from, a.to, logp, fsg_model_word_add(fsg, a.word.c_str()));
  }
  // chains of null arcs (a word left out, then the next) are followed only once closed over
  glist_free(fsg_model_null_trans_closure(fsg, nullptr));
  for (int s : g.pause_states) {
    fsg_model_add_silence(fsg, "<sil>", s, static_cast<float>(g.silence_probability));
    if (g.noise_probability > 0) fsg_model_add_silence(fsg, "[NOISE]", s, static_cast<float>(g.noise_probability));
  }
  const int set = ps_set_fsg(impl_->ps, "grammar", fsg);
  fsg_model_free(fsg);  // the search keeps its own reference
  if (set < 0) throw std::logic_error("pocketsphinx: the grammar was refused (a word missing from the dictionary?)");
  ps_set_search(impl_->ps, "grammar");
  impl_->run(samples);
  return impl_->best_path();
}

std::int64_t Decoder::frame_start_sample(int frame) const {
  const std::int64_t s = frame * impl_->shift + kWindowSamples / 2 - impl_->shift / 2 - kPadSamples;
  return std::max<std::int64_t>(0, s);
}

}  // namespace fapcast
