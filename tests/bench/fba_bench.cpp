// FBA stream: bitrates in both profiles (the standard syntax, default and archival intra periods;
// the fapcast profile) at fap_quant 0, 1, 2, 4, 8 against gzip -9 and xz -9 of the strict .fap
// text holding the same quantised values, on the Xface samples (every FAP they carry), on
// SYNTHETIC lip/jaw/tongue tracks (sums of low-frequency sinusoids and a low-passed random walk,
// not motion capture) and on a SYNTHETIC track of the real synthesiser (`fapcast say` of a
// one-minute text with the default voice, every FAP it writes); and encode/decode speed against
// reading the same frames as .fap text and against the frame-at-a-time decoder (one access unit
// per frame, as RTP carries them).
// Run: build/rel/tests/fba_bench   (counters: kbit/s at 25 fps, and ratios)
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/fba/fba_quantiser.hpp"
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/fba/fba_stream.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace {
using namespace fapcast;
namespace fs = std::filesystem;

constexpr double kFps = 25.0;

FapMask lip_jaw_tongue() {
  FapMask m;
  for (int g : {2, 6, 8})
    for (int n = fap_group(g).first; n <= fap_group(g).last; ++n) m.set(n);
  return m;
}

// SYNTHETIC speech-like lip/jaw/tongue motion: a 4-5 Hz syllable rhythm with pauses, each FAP a
// sum of low-frequency sinusoids plus a low-passed random walk, rounded to whole FAPU.
FapSequence synthetic_track(double seconds, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> phase(0, 2 * std::numbers::pi), unit(0, 1);
  std::normal_distribution<double> noise(0, 1);
  const FapMask mask = lip_jaw_tongue();
  FapSequence seq{"synthetic", {25, 1}, {}};
  const auto frames = static_cast<std::size_t>(seconds * kFps);
  std::map<int, std::array<double, 6>> p;  // amplitude, f1, f2, phases, walk
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
    if (mask.test(n)) p[n] = {n == 3 ? 260.0 : 40 + 80 * unit(rng), 3.8 + unit(rng), 0.3 + 0.5 * unit(rng), phase(rng), phase(rng), 0};
  double envelope = 1, walk_state = 0;
  for (std::size_t k = 0; k < frames; ++k) {
    const double t = static_cast<double>(k) / kFps;
    // Phrases of ~2-4 s separated by short pauses, with a smooth attack and release.
    const double phrase = std::sin(2 * std::numbers::pi * 0.3 * t) + 0.6;
    envelope += 0.15 * ((phrase > 0 ? 1.0 : 0.1) - envelope);
    walk_state = 0.9 * walk_state + noise(rng);
    FapFrame f;
    for (auto& [n, q] : p) {
      q[5] = 0.95 * q[5] + 0.8 * noise(rng);  // per-FAP low-passed random walk
      const double v = q[0] * envelope * (0.5 + 0.5 * std::sin(2 * std::numbers::pi * q[1] * t + q[3])) +
                       0.3 * q[0] * std::sin(2 * std::numbers::pi * q[2] * t + q[4]) + 3 * q[5] + 2 * walk_state;
      f.set(n, static_cast<std::int32_t>(std::lround(v)));
    }
    seq.frames.push_back(f);
  }
  return seq;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Bytes `command` (gzip -9 / xz -9) makes of `text`, run as a subprocess on a temporary file.
std::size_t compressed_size(const std::string& text, const std::string& command) {
  const fs::path tmp = fs::temp_directory_path() / ("fba_bench_" + std::to_string(::getpid()) + ".fap");
  std::ofstream(tmp, std::ios::binary) << text;
  const std::string cmd = command + " -c '" + tmp.string() + "' | wc -c";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  unsigned long long bytes = 0;
  if (std::fscanf(pipe, "%llu", &bytes) != 1) bytes = 0;
  ::pclose(pipe);
  fs::remove(tmp);
  return static_cast<std::size_t>(bytes);
}

struct Source {
  std::string name;
  FapSequence seq;
};

// SYNTHETIC: what `fapcast say` makes of about a minute of text (the default voice, 25 fps).
FapSequence say_track() {
  const char* text =
      "Archiving and broadcasting want the compact form of a facial animation track, not text. The encoder "
      "sizes the coding ranges to the data at each intra frame, and the decoder never trusts its input: it "
      "reads zeros past the end, keeps a sticky error, and after corruption it resynchronises at the next "
      "plane start code, reporting how many frames were lost. Speech moves the lips and the jaw in a rhythm "
      "of four to six syllables a second, on a slowly moving rest position, with pauses between phrases. A "
      "predictor that follows that rhythm removes most of the motion, and an adaptive model learns what is "
      "left. Whatever the period between intra frames, every value decodes within half a quantiser step of "
      "the input, and nothing drifts, however long the track. The quick brown fox jumps over the lazy dog, "
      "while seven wise men measure the weather on the northern shore, and a bright choir sings through the "
      "long evening. Tomorrow we shall walk along the river to the old mill, count the boats, and come home "
      "before the rain. Then we shall sit by the fire, read a little, and sleep.";
  const fs::path out = fs::temp_directory_path() / ("fba_bench_say_" + std::to_string(::getpid()) + ".fap");
  const std::string cmd = std::string("'") + FAPCAST_EXE + "' say \"" + text + "\" -o '" + out.string() + "' --quiet 2>&1";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run fapcast say");
  std::string log;
  for (int c; (c = std::fgetc(pipe)) != EOF;) log.push_back(static_cast<char>(c));
  if (::pclose(pipe) != 0) throw std::runtime_error("fapcast say failed: " + log);
  FapSequence seq = read_fap_text(read_text(out), out.string()).sequence;
  fs::remove(out);
  return seq;
}

std::vector<Source> sources() {
  std::vector<Source> out;
  for (const char* s : {"anger", "beg", "disgust", "fear", "happy-for", "hate", "joy", "pride"}) {
    const fs::path p = fs::path(FAPCAST_TEST_DATA) / "xface" / (std::string(s) + ".fap");
    out.push_back({std::string("xface/") + s, read_fap_text(read_text(p), p.string()).sequence});
  }
  out.push_back({"SYNTHETIC-60s", synthetic_track(60, 1)});
  out.push_back({"SYNTHETIC-300s", synthetic_track(300, 2)});
  out.push_back({"SYNTHETIC-say-60s", say_track()});
  return out;
}

constexpr int kSources = 11;  // what sources() makes: 8 Xface clips, 3 SYNTHETIC tracks

const std::vector<Source>& all_sources() {
  static const std::vector<Source> s = sources();
  if (s.size() != kSources) throw std::logic_error("bench: kSources is out of date");
  return s;
}

double kbps(std::size_t bytes, std::size_t frames) { return 8.0 * static_cast<double>(bytes) / (static_cast<double>(frames) / kFps) / 1000.0; }

// The strict .fap text of `seq` with every value on the fap_quant step grid (what the standard
// syntax decodes to): the baseline gzip -9 and xz -9 compress.
std::string quantised_text(const FapSequence& seq, int q) {
  FapSequence quantised = seq;
  quantised.name = "track";
  for (FapFrame& f : quantised.frames)
    for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap)
      if (f.mask.test(fap)) f.set(fap, fba_quantise(f.value(fap), fba_step(fap, q)) * fba_step(fap, q));
  return write_fap_text(quantised);
}

// Bytes of `seq` in the standard syntax with `options`, or 0 where it cannot code the values
// (beyond +/-1860 at fap_quant 0).
std::size_t standard_bytes(const FapSequence& seq, FbaEncoderOptions options) {
  try {
    return encode_fba(seq, options).size();
  } catch (const FbaEncodeError&) {
    return 0;
  }
}

// One row of the table: bitrates of the standard syntax with the default options (intra period
// 10 s, ranges sized to the data) and with the archival preset (20 s), of the fapcast profile
// (20 s, predictors and references chosen), and of gzip -9 and xz -9 of the same quantised
// values as strict .fap text. Ratios are xz bytes / FBA bytes (0: not codable in the standard).
void BM_Bitrate(benchmark::State& state) {
  const Source& src = all_sources()[static_cast<std::size_t>(state.range(0))];
  const int q = static_cast<int>(state.range(1));
  state.SetLabel(src.name + " q" + std::to_string(q));
  FbaEncoderOptions fapcast{.profile = FbaProfile::kFapcast, .fap_quant = q};
  std::vector<std::uint8_t> fba;
  for (auto _ : state) {
    fba = encode_fba(src.seq, fapcast);
    benchmark::DoNotOptimize(fba.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * src.seq.frames.size()));  // encode frames/s
  const std::size_t standard = standard_bytes(src.seq, {.fap_quant = q});
  const std::size_t archive = standard_bytes(src.seq, fba_archive_options(FbaProfile::kStandard, q, src.seq.rate));
  const std::string text = quantised_text(src.seq, q);
  const std::size_t gz = compressed_size(text, "gzip -9"), xz = compressed_size(text, "xz -9");
  const std::size_t n = src.seq.frames.size();
  const auto ratio = [&](std::size_t bytes) { return bytes == 0 ? 0.0 : static_cast<double>(xz) / static_cast<double>(bytes); };
  state.counters["std_kbps"] = kbps(standard, n);
  state.counters["std_archive_kbps"] = kbps(archive, n);
  state.counters["fapcast_kbps"] = kbps(fba.size(), n);
  state.counters["gzip_kbps"] = kbps(gz, n);
  state.counters["xz_kbps"] = kbps(xz, n);
  state.counters["xz_over_std"] = ratio(standard);
  state.counters["xz_over_std_archive"] = ratio(archive);
  state.counters["xz_over_fapcast"] = ratio(fba.size());
}

void bitrate_args(benchmark::internal::Benchmark* b) {
  for (int s = 0; s < kSources; ++s)
    for (int q : {0, 1, 2, 4, 8}) b->Args({s, q});
}
BENCHMARK(BM_Bitrate)->Apply(bitrate_args)->Unit(benchmark::kMillisecond);

// Decoding speed on the 300 s synthetic track, frames/s; and the alternative: parsing .fap text.
void BM_DecodeFba(benchmark::State& state) {
  const FapSequence& seq = all_sources()[9].seq;
  const auto fba = encode_fba(seq, {.profile = static_cast<FbaProfile>(state.range(1)), .fap_quant = static_cast<int>(state.range(0))});
  for (auto _ : state) {
    auto r = decode_fba(fba);
    benchmark::DoNotOptimize(r.sequence.frames.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * seq.frames.size()));
}
BENCHMARK(BM_DecodeFba)->Args({1, 0})->Args({8, 0})->Args({0, 1})->Args({1, 1})->Unit(benchmark::kMillisecond);

// The same frames as access units (start code and alignment per frame), decoded one by one.
void BM_DecodeAccessUnits(benchmark::State& state) {
  const FapSequence& seq = all_sources()[9].seq;
  const auto profile = static_cast<FbaProfile>(state.range(1));
  FbaFrameEncoder encoder({.profile = profile, .fap_quant = static_cast<int>(state.range(0))}, seq.rate);
  std::vector<FbaAccessUnit> units(seq.frames.size());
  for (std::size_t k = 0; k < units.size(); ++k)
    if (encoder.encode(seq.frames[k], units[k])) throw std::runtime_error("bench: encode");
  for (auto _ : state) {
    FbaFrameDecoder decoder(profile);
    FapFrame frame;
    for (const auto& u : units) {
      if (decoder.decode(u.bytes, frame)) throw std::runtime_error("bench: decode");
      benchmark::DoNotOptimize(frame.values.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * seq.frames.size()));
}
BENCHMARK(BM_DecodeAccessUnits)->Args({1, 0})->Args({8, 0})->Args({1, 1})->Unit(benchmark::kMillisecond);

void BM_EncodeFba(benchmark::State& state) {
  const FapSequence& seq = all_sources()[9].seq;
  for (auto _ : state) {
    auto b = encode_fba(seq, {.profile = static_cast<FbaProfile>(state.range(1)), .fap_quant = static_cast<int>(state.range(0))});
    benchmark::DoNotOptimize(b.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * seq.frames.size()));
}
BENCHMARK(BM_EncodeFba)->Args({1, 0})->Args({8, 0})->Args({1, 1})->Unit(benchmark::kMillisecond);

void BM_ReadFapText(benchmark::State& state) {
  const FapSequence& seq = all_sources()[9].seq;
  const std::string text = write_fap_text(seq);
  for (auto _ : state) {
    auto r = read_fap_text(text, "synthetic.fap");
    benchmark::DoNotOptimize(r.sequence.frames.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * seq.frames.size()));
}
BENCHMARK(BM_ReadFapText)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
