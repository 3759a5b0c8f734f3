// The .fap text reader and writer: the eight real Xface files, every dialect generated from
// them, random round trips, the header rules, and the named bad inputs with their golden errors.
#include "fapcast/codec/fap_text.hpp"

#include "fapcast/core/input_error.hpp"
#include "fapcast/core/file_io.hpp"
#include "support/fap_sequences.hpp"
#include "support/file_bytes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kData = FAPCAST_TEST_DATA;

std::string xface_text(const std::string& file) {
  return read_file(kData / "xface" / file);
}

// "3-18 23-26" -> FAPs 3..18 and 23..26.
FapMask mask_of(const std::string& spans) {
  FapMask m;
  std::istringstream in(spans);
  std::string span;
  while (in >> span) {
    const auto dash = span.find('-');
    const int a = std::stoi(span.substr(0, dash));
    const int b = dash == std::string::npos ? a : std::stoi(span.substr(dash + 1));
    for (int n = a; n <= b; ++n) m.set(n);
  }
  return m;
}

// Expected facts about each real file, counted independently of this reader (a Python
// one-liner over the raw text: split on whitespace, sum the value tokens).
struct XfaceCase {
  const char* file;
  std::size_t frames;
  const char* first_mask;    // FAPs masked in frame 0
  const char* any_mask;      // FAPs masked in some frame
  std::int32_t open_jaw_min; // FAP 3 (unidirectional: negatives must survive)
  std::int32_t open_jaw_max;
  std::int64_t value_sum;    // every masked low-level value of every frame
};

const XfaceCase kXface[] = {
    {"anger.fap", 108, "3-20 23-26 31-42 48-60 63", "3-20 23-26 31-42 48-60 63", -6, 315, -672292},
    {"beg.fap", 107, "3-18 23-26 31-42 48-60 63", "3-20 23-26 31-42 48-60 63", -7, 313, 426433},
    {"disgust.fap", 107, "3-18 23-26 31-42 48-63", "3-20 23-26 31-42 48-63", -7, 313, -369713},
    {"fear.fap", 107, "3-26 31-42 48-60 63", "3-26 31-42 48-60 63", 0, 713, -694469},
    {"happy-for.fap", 107, "3-18 23-26 39-42 48-60 63", "3-20 23-26 39-42 48-60 63", -7, 313, 75294},
    {"hate.fap", 107, "3-18 23-26 31-42 48-63", "3-20 23-26 31-42 48-63", -7, 313, -80554},
    {"joy.fap", 108, "3-26 39-42 48-60 63", "3-26 39-42 48-60 63", -6, 315, -574520},
    {"pride.fap", 107, "3-18 23-26 39-42 48-60 63", "3-20 23-26 39-42 48-60 63", 0, 363, -3484},
};

class XfaceFile : public testing::TestWithParam<XfaceCase> {};

TEST_P(XfaceFile, ParsesWithItsFramesFpsAndMasks) {
  const XfaceCase& c = GetParam();
  const FapTextRead r = read_fap_text(xface_text(c.file), c.file);
  EXPECT_EQ(r.info.version, "2.1");
  EXPECT_EQ(r.info.dialect, FapTextDialect::kStrict);
  EXPECT_EQ(r.info.header_frame_count, c.frames);
  EXPECT_EQ(r.info.frame_records, c.frames);
  EXPECT_TRUE(r.info.crlf);
  EXPECT_FALSE(r.info.skipped_frames || r.info.real_valued_tokens || r.info.header_count_short);
  EXPECT_TRUE(r.info.warnings.empty()) << r.info.warnings.front();
  EXPECT_EQ(r.info.describe(), "68-token masks, CRLF");
  EXPECT_EQ(r.sequence.name, R"(C:\Users\balci\Work\FACE\exml2fap\files\TempFile)");
  EXPECT_EQ(r.sequence.rate, (FrameRate{25, 1}));
  ASSERT_EQ(r.sequence.frames.size(), c.frames);
  EXPECT_EQ(r.sequence.frames.front().mask, mask_of(c.first_mask));

  FapMask any;
  std::int32_t jaw_min = INT32_MAX, jaw_max = INT32_MIN;
  std::int64_t sum = 0;
  for (const FapFrame& f : r.sequence.frames) {
    for (int n = 1; n <= kFapCount; ++n) {
      if (f.mask.test(n)) any.set(n);
      else EXPECT_EQ(f.value(n), 0) << "unmasked FAP " << n << " must read as 0";
      sum += f.value(n);
    }
    jaw_min = std::min(jaw_min, f.value(3));
    jaw_max = std::max(jaw_max, f.value(3));
  }
  EXPECT_EQ(any, mask_of(c.any_mask));
  EXPECT_EQ(jaw_min, c.open_jaw_min);
  EXPECT_EQ(jaw_max, c.open_jaw_max);
  EXPECT_EQ(sum, c.value_sum);
}

INSTANTIATE_TEST_SUITE_P(Xface, XfaceFile, testing::ValuesIn(kXface),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           std::replace_if(n.begin(), n.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                           return n;
                         });

// ---- dialects generated from the real files --------------------------------------------------

// A .fap text as header + (mask, values) records of tokens, to rewrite programmatically.
struct Records {
  std::vector<std::string> header;
  std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> frames;
};

std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> t;
  for (std::string s; in >> s;) t.push_back(s);
  return t;
}

Records records_of(const std::string& text) {
  std::istringstream in(text);
  Records r;
  std::string line;
  std::getline(in, line);
  r.header = tokens(line);
  std::string mask, values;
  while (std::getline(in, mask) && std::getline(in, values)) r.frames.push_back({tokens(mask), tokens(values)});
  return r;
}

std::string join(const std::vector<std::string>& t, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < t.size(); ++i) s += (i ? sep : "") + t[i];
  return s;
}

std::string text_of(const Records& r, const std::string& sep = " ", const std::string& eol = "\n") {
  std::string s = join(r.header, sep) + eol;
  for (const auto& [m, v] : r.frames) s += join(m, sep) + eol + join(v, sep) + eol;
  return s;
}

// A dialect variant: rewrites the file's records/text and the frames the reader must yield.
struct FapTextVariant {
  const char* name;
  std::function<std::string(Records&, std::vector<FapFrame>&)> make;
  std::function<bool(const FapTextInfo&)> saw;  // what the reader must report
};

using test::replace_all;

const FapTextVariant kVariants[] = {
    {"Lf", [](Records& r, auto&) { return text_of(r); },
     [](const FapTextInfo& i) { return !i.crlf && !i.tabs && i.describe() == "68-token masks"; }},
    {"Crlf", [](Records& r, auto&) { return text_of(r, " ", "\r\n"); },
     [](const FapTextInfo& i) { return i.crlf; }},
    {"Tabs", [](Records& r, auto&) { return text_of(r, "\t"); },
     [](const FapTextInfo& i) { return i.tabs; }},
    {"RaggedSpaces", [](Records& r, auto&) { return "  " + text_of(r, " \t  ", "   \n"); },
     [](const FapTextInfo& i) { return i.tabs; }},
    {"CommentsAndBlankLines",
     [](Records& r, auto&) {
       std::string s = "# exported by a test\n\n" + join(r.header, " ") + "\n";
       for (const auto& [m, v] : r.frames) s += "  # mask\n" + join(m, " ") + "\n\n#values\n" + join(v, " ") + "\n";
       return s + "# end\n";
     },
     [](const FapTextInfo& i) { return i.comments; }},
    {"Utf8Bom", [](Records& r, auto&) { return "\xEF\xBB\xBF" + text_of(r, " ", "\r\n"); },
     [](const FapTextInfo& i) { return i.describe() == "68-token masks, UTF-8 BOM, CRLF"; }},
    {"Version20", [](Records& r, auto&) { r.header[0] = "2.0"; return text_of(r); },
     [](const FapTextInfo& i) { return i.version == "2.0"; }},
    {"NameWithSpaces",
     [](Records& r, auto&) {
       r.header = {"2.1", "AU", "Interpolation_1111.fap", r.header[2], r.header[3]};
       return text_of(r);
     },
     [](const FapTextInfo& i) { return i.name_has_spaces; }},
    {"NoFinalNewline", [](Records& r, auto&) { auto s = text_of(r); s.pop_back(); return s; },
     [](const FapTextInfo& i) { return i.warnings.empty(); }},
    {"Mask69", [](Records& r, auto&) {
       for (auto& [m, v] : r.frames) m.insert(m.begin(), "0");
       return text_of(r);
     },
     [](const FapTextInfo& i) { return i.dialect == FapTextDialect::kMask69; }},
    {"Mask69WithVisemeAndExpression",
     [](Records& r, std::vector<FapFrame>& want) {
       for (std::size_t k = 0; k < r.frames.size(); ++k) {
         auto& [m, v] = r.frames[k];
         m.insert(m.begin(), "0");
         m[1] = m[2] = "1";
         v.insert(v.begin() + 1, {std::to_string(k % 15), std::to_string(k % 7)});
         want[k].mask.set(1).set(2);
         want[k].viseme = {static_cast<std::uint8_t>(k % 15), 0, 63, false};
         want[k].expression = {static_cast<std::uint8_t>(k % 7), 63, 0, 0, false, false};
       }
       return text_of(r);
     },
     [](const FapTextInfo& i) { return i.dialect == FapTextDialect::kMask69; }},
    {"VisemeWith4AndExpressionWith6Fields",
     [](Records& r, std::vector<FapFrame>& want) {
       for (std::size_t k = 0; k < r.frames.size(); ++k) {
         auto& [m, v] = r.frames[k];
         m[0] = m[1] = "1";
         const auto u8 = [](std::size_t x) { return static_cast<std::uint8_t>(x); };
         want[k].mask.set(1).set(2);
         want[k].viseme = {u8(k % 15), u8((k + 3) % 15), u8(k % 64), k % 2 == 1};
         want[k].expression = {u8(k % 7), u8(k % 64), u8((k + 1) % 7), u8((2 * k) % 64), k % 2 == 0, k % 2 == 1};
         const auto& w = want[k];
         v.insert(v.begin() + 1,
                  {std::to_string(w.viseme.select1), std::to_string(w.viseme.select2), std::to_string(w.viseme.blend),
                   std::to_string(w.viseme.def), std::to_string(w.expression.select1),
                   std::to_string(w.expression.intensity1), std::to_string(w.expression.select2),
                   std::to_string(w.expression.intensity2), std::to_string(w.expression.init_face),
                   std::to_string(w.expression.def)});
       }
       return text_of(r);
     },
     [](const FapTextInfo& i) { return i.dialect == FapTextDialect::kStrict; }},
    {"SkippedFramesAreHeld",
     [](Records& r, std::vector<FapFrame>& want) {
       Records kept = r;
       kept.frames.clear();
       for (std::size_t k = 0; k < r.frames.size(); ++k) {
         if (k % 5 == 3 || k % 11 == 4) want[k] = want[k - 1];
         else kept.frames.push_back(r.frames[k]);
       }
       return text_of(kept);
     },
     [](const FapTextInfo& i) { return i.skipped_frames && i.frame_records < i.header_frame_count; }},
    {"RealValuedTokensAreRounded",
     [](Records& r, std::vector<FapFrame>& want) {
       for (std::size_t k = 0; k < r.frames.size(); ++k) {
         auto& v = r.frames[k].second;
         int fap = 0;
         for (std::size_t i = 1; i < v.size(); ++i) {
           while (!want[k].mask.test(++fap)) {}
           if (i % 3 == 0) v[i] += ".4";  // rounds back to v
           if (i % 3 == 1) {                // half rounds away from zero
             v[i] += ".5";
             const std::int32_t x = want[k].value(fap);
             want[k].set(fap, x + (v[i][0] == '-' ? -1 : 1));
           }
         }
       }
       return text_of(r);
     },
     [](const FapTextInfo& i) {
       return i.real_valued_tokens && i.warning_count > 100 && i.warnings.size() == kFapTextMaxWarnings + 1;
     }},
    {"HeaderCountOneTooMany",
     [](Records& r, auto&) { r.header[3] = std::to_string(std::stoi(r.header[3]) + 1); return text_of(r); },
     [](const FapTextInfo& i) { return i.header_count_short && i.warning_count == 1; }},
};

class XfaceDialect : public testing::TestWithParam<std::tuple<XfaceCase, FapTextVariant>> {};

TEST_P(XfaceDialect, ReadsAsExpectedAndRoundTripsThroughBothWriters) {
  const auto& [c, variant] = GetParam();
  // Each file is read and split once for all its variants (keeps the suite fast under ASan).
  static std::map<std::string, std::pair<FapTextRead, Records>> cache;
  if (!cache.count(c.file))
    cache[c.file] = {read_fap_text(xface_text(c.file), c.file),
                     records_of(replace_all(xface_text(c.file), "\r\n", "\n"))};
  const FapTextRead& original = cache[c.file].first;
  Records rec = cache[c.file].second;
  std::vector<FapFrame> want = original.sequence.frames;
  const std::string text = variant.make(rec, want);

  const FapTextRead r = read_fap_text(text, "variant.fap");
  EXPECT_TRUE(variant.saw(r.info)) << r.info.describe();
  EXPECT_EQ(r.sequence.rate, original.sequence.rate);
  ASSERT_EQ(r.sequence.frames, want);

  // read, write, read gives the same frames (and the writer is a fixed point).
  const std::string strict = write_fap_text(r.sequence);
  const FapTextRead again = read_fap_text(strict, "strict.fap");
  EXPECT_EQ(again.sequence.frames, want);
  EXPECT_EQ(again.sequence.name, fap_text_name(r.sequence.name));
  EXPECT_EQ(again.info.describe(), "68-token masks");
  EXPECT_EQ(write_fap_text(again.sequence), strict);

  const FapTextRead from69 = read_fap_text(write_fap_text(r.sequence, FapTextDialect::kMask69), "69.fap");
  EXPECT_EQ(from69.info.dialect, FapTextDialect::kMask69);
  std::vector<FapFrame> want69;
  for (const auto& f : want) want69.push_back(as_mask69(f));
  EXPECT_EQ(from69.sequence.frames, want69);
}

INSTANTIATE_TEST_SUITE_P(Xface, XfaceDialect, testing::Combine(testing::ValuesIn(kXface), testing::ValuesIn(kVariants)),
                         [](const auto& info) {
                           std::string n = std::get<0>(info.param).file;
                           n = n.substr(0, n.find('.'));
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n + "_" + std::get<1>(info.param).name;
                         });

// ---- random round trips ----------------------------------------------------------------------

TEST(FapTextRandom, StrictAnd69RoundTrip) {
  const std::uint64_t seed = test::test_seed(test::kFapSequenceSeed);
  SCOPED_TRACE("reproduce with FAPCAST_SEED=" + std::to_string(seed));
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 60; ++trial) {
    const FapSequence seq = test::random_fap_sequence(rng, static_cast<std::size_t>(trial % 12));
    const std::string strict = write_fap_text(seq);
    FapSequence want = seq;
    want.name = fap_text_name(seq.name);
    const FapTextRead r = read_fap_text(strict, "random.fap");
    ASSERT_EQ(r.sequence, want) << strict;
    EXPECT_EQ(r.info.describe(), "68-token masks");

    const FapTextRead r69 = read_fap_text(write_fap_text(seq, FapTextDialect::kMask69), "random69.fap");
    for (auto& f : want.frames) f = as_mask69(f);
    ASSERT_EQ(r69.sequence, want);
    EXPECT_EQ(mask69_lossy_frames(r69.sequence), 0u);
  }
}

// The frame-at-a-time writer gives write_fap_text's bytes and the same players' notes, for
// every layout (strict, 69 tokens, each player).
TEST(FapTextRandom, FrameWriterIsTheWholeWriter) {
  const std::uint64_t seed = test::test_seed(test::kFapSequenceSeed);
  SCOPED_TRACE("reproduce with FAPCAST_SEED=" + std::to_string(seed));
  std::mt19937_64 rng(seed);
  std::vector<FapTextWriteOptions> layouts{{}, {FapTextDialect::kMask69, std::nullopt}};
  for (const FapPlayer p : {FapPlayer::kXface, FapPlayer::kGreta, FapPlayer::kVreng}) layouts.push_back({FapTextDialect::kStrict, p});
  for (int trial = 0; trial < 40; ++trial) {
    FapSequence seq = test::random_fap_sequence(rng, static_cast<std::size_t>(trial % 12));
    if (trial % 3 == 0) seq.rate = {30000, 1001};  // not a whole rate: Xface refuses, the others note it
    for (const FapTextWriteOptions& o : layouts) {
      std::string whole;
      try {
        whole = write_fap_text(seq, o);
      } catch (const std::invalid_argument&) {
        EXPECT_THROW(FapTextFrameWriter(seq.rate, o), std::invalid_argument);
        continue;
      }
      FapTextFrameWriter writer(seq.rate, o);
      std::string body;
      for (const FapFrame& f : seq.frames) writer.append(body, f);
      EXPECT_EQ(writer.header(seq.name) + body, whole);
      EXPECT_EQ(fap_text_player_notes(writer.stats(), o), fap_text_player_notes(seq, o));
    }
  }
}

// ---- the header ------------------------------------------------------------------------------

struct FpsCase {
  const char* token;
  FrameRate rate;
};

class FapTextFps : public testing::TestWithParam<FpsCase> {};

TEST_P(FapTextFps, MapsToAnExactRateAndBack) {
  const auto& [token, rate] = GetParam();
  const FapTextRead r = read_fap_text(std::string("2.1 x ") + token + " 0\n", "fps.fap");
  EXPECT_EQ(r.sequence.rate, rate);
  EXPECT_EQ(r.sequence.rate.numerator, rate.numerator);  // reduced, not merely equal
  EXPECT_EQ(r.sequence.rate.denominator, rate.denominator);
  EXPECT_EQ(read_fap_text("2.1 x " + fap_text_fps(rate) + " 0\n", "").sequence.rate, rate);
}

INSTANTIATE_TEST_SUITE_P(Rates, FapTextFps,
                         testing::Values(FpsCase{"25", {25, 1}}, FpsCase{"25.0", {25, 1}}, FpsCase{"12.5", {25, 2}},
                                         FpsCase{"29.97", {30000, 1001}}, FpsCase{"29.970", {30000, 1001}},
                                         FpsCase{"23.976", {24000, 1001}}, FpsCase{"23.98", {24000, 1001}},
                                         FpsCase{"59.94", {60000, 1001}}, FpsCase{"119.88", {120000, 1001}},
                                         FpsCase{"29.9", {299, 10}}, FpsCase{"29.970000", {2997, 100}},
                                         FpsCase{"1000", {1000, 1}}, FpsCase{"0.000001", {1, 1000000}}));

TEST(FapTextFps, WriterRefusesRatesWithoutAnExactDecimal) {
  EXPECT_THROW(fap_text_fps({10, 3}), std::invalid_argument);
  EXPECT_THROW(fap_text_fps({1001, 1}), std::invalid_argument);
  EXPECT_EQ(fap_text_fps({30000, 1001}), "29.97");
  EXPECT_EQ(fap_text_fps({24000, 1001}), "23.976");
  EXPECT_EQ(fap_text_fps({2997, 100}), "29.97000");  // 29.9700 would read as 30000/1001
  EXPECT_EQ(fap_text_fps({50, 2}), "25");
}

// A 68-token mask with only FAP 3 (open_jaw) set, and one record of it.
const std::string kMaskFap3 = [] {
  std::string m = "0 0 1";
  for (int i = 0; i < 65; ++i) m += " 0";
  return m;
}();

std::string record(std::uint64_t frame, std::int32_t open_jaw) {
  return kMaskFap3 + "\n" + std::to_string(frame) + " " + std::to_string(open_jaw) + "\n";
}

// A file with `held` frames (0..held-1) whose header claims `claimed`.
std::string short_file(std::uint64_t claimed, std::uint64_t held) {
  std::string s = "2.1 short 25 " + std::to_string(claimed) + "\n";
  for (std::uint64_t k = 0; k < held; ++k) s += record(k, static_cast<std::int32_t>(k));
  return s;
}

struct CountCase {
  std::uint64_t claimed;
  std::uint64_t held;
  bool accepted;
};

class FapTextHeaderCount : public testing::TestWithParam<CountCase> {};

// Up to max(1, claimed/100) frames short is accepted with a warning; more is refused.
TEST_P(FapTextHeaderCount, ShortFilesWithinToleranceLoad) {
  const auto& [claimed, held, accepted] = GetParam();
  const std::string text = short_file(claimed, held);
  if (!accepted) {
    try {
      read_fap_text(text, "short.fap");
      FAIL() << "accepted " << held << " of " << claimed;
    } catch (const InputError& e) {
      EXPECT_EQ(e.rule(), "header-count-beyond-file");
      EXPECT_EQ(e.where().line, 1u);
    }
    return;
  }
  const FapTextRead r = read_fap_text(text, "short.fap");
  EXPECT_EQ(r.sequence.frames.size(), held);
  EXPECT_EQ(r.info.header_count_short, claimed != held);
  EXPECT_EQ(r.info.warning_count, claimed != held ? 1u : 0u);
}

INSTANTIATE_TEST_SUITE_P(Tolerance, FapTextHeaderCount,
                         testing::Values(CountCase{108, 108, true}, CountCase{108, 107, true},
                                         CountCase{108, 106, false}, CountCase{1, 0, true},
                                         CountCase{2, 0, false}, CountCase{0, 0, true},
                                         CountCase{300, 297, true}, CountCase{300, 296, false},
                                         CountCase{1000000, 3, false}));

TEST(FapTextLimits, SkipsHoldAtMostTheLimit) {
  auto file = [](std::uint64_t second) {
    return "2.1 gap 25 " + std::to_string(second + 1) + "\n" + record(0, 7) + record(second, 9);
  };
  const FapTextRead ok = read_fap_text(file(kFapTextMaxHeldFrames + 1), "gap.fap");
  ASSERT_EQ(ok.sequence.frames.size(), kFapTextMaxHeldFrames + 2);
  EXPECT_EQ(ok.sequence.frames[kFapTextMaxHeldFrames].value(3), 7);  // held
  EXPECT_EQ(ok.sequence.frames.back().value(3), 9);
  EXPECT_EQ(ok.info.frame_records, 2u);
  try {
    read_fap_text(file(kFapTextMaxHeldFrames + 2), "gap.fap");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "frame-gap");
    EXPECT_EQ(e.where().line, 5u);
  }
}

TEST(FapTextLimits, FramesBeforeTheFirstRecordAreNeutral) {
  const FapTextRead r = read_fap_text("2.1 late 25 3\n" + record(2, 5), "late.fap");
  ASSERT_EQ(r.sequence.frames.size(), 3u);
  EXPECT_TRUE(r.sequence.frames[0].mask.none());
  EXPECT_TRUE(r.sequence.frames[1].mask.none());
  EXPECT_EQ(r.sequence.frames[2].value(3), 5);
  EXPECT_TRUE(r.info.skipped_frames);
  ASSERT_EQ(r.info.warnings.size(), 1u);
  EXPECT_EQ(r.info.warnings[0], "late.fap:3: first-frame: the first frame is 2; frames before it are neutral");
}

TEST(FapTextLimits, HeaderCountAboveTheLimitIsRefusedAtOnce) {
  try {
    read_fap_text("2.1 big 25 1000000000000\n", "big.fap");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), "header-count");
  }
}

// ---- the writer ------------------------------------------------------------------------------

TEST(FapTextWriter, WritesTheStrictProfileExactly) {
  FapSequence s;
  s.name = "two words\n";
  s.rate = {25, 1};
  FapFrame a;
  a.set(3, -12).set(68, 2147483647);
  a.mask.set(1);
  a.viseme = {1, 2, 40, true};
  FapFrame b;
  b.mask.set(2);
  b.expression = {3, 63, 0, 0, false, false};
  s.frames = {a, b};
  std::string zeros66;
  for (int i = 0; i < 64; ++i) zeros66 += "0 ";
  const std::string want = "2.1 two_words_ 25 2\n"
                           "1 0 1 " + zeros66 + "1\n"
                           "0 1 2 40 1 -12 2147483647\n"
                           "0 1 0 " + zeros66 + "0\n"
                           "1 3 63 0 0 0 0\n";
  EXPECT_EQ(write_fap_text(s), want);
  const std::string want69 = "2.1 two_words_ 25 2\n"
                             "0 1 0 1 " + zeros66 + "1\n"
                             "0 1 -12 2147483647\n"
                             "0 0 1 0 " + zeros66 + "0\n"
                             "1 3\n";
  EXPECT_EQ(write_fap_text(s, FapTextDialect::kMask69), want69);
  EXPECT_EQ(mask69_lossy_frames(s), 1u);  // frame a's viseme has select2/blend/def; b is carried whole
}

TEST(FapTextWriter, RefusesWhatTheReaderWouldRefuse) {
  // (The frame-count limit is not tested: a sequence past it would take 300 MB.)
  FapSequence s;
  s.frames.resize(1);
  s.rate = {10, 3};
  EXPECT_THROW(write_fap_text(s), std::invalid_argument);
}

TEST(FapTextWriter, NamesBecomeOneToken) {
  EXPECT_EQ(fap_text_name("AU Interpolation\t1111.fap"), "AU_Interpolation_1111.fap");
  EXPECT_EQ(fap_text_name(""), "unnamed");
  EXPECT_EQ(fap_text_name("caf\xC3\xA9"), "caf\xC3\xA9");
  EXPECT_EQ(fap_text_name("caf\xE9 x"), "caf\xEF\xBF\xBD_x");
  EXPECT_EQ(fap_text_name(std::string("a\0b", 3)), "a_b");
}

TEST(FapTextReader, RepairsANameThatIsNotUtf8) {
  const FapTextRead r = read_fap_text("2.1 caf\xE9 25 0\n", "latin1.fap");
  EXPECT_EQ(r.sequence.name, "caf\xEF\xBF\xBD");
  ASSERT_EQ(r.info.warnings.size(), 1u);
  EXPECT_EQ(r.info.warnings[0], "latin1.fap:1: name-encoding: the name is not UTF-8; invalid bytes became U+FFFD");
}

// ---- named bad inputs and their golden errors ------------------------------------------------

const fs::path kBad = kData / "fap" / "bad";

std::map<std::string, std::string> golden_errors() {
  std::istringstream in(read_file(kBad / "expected-errors.txt"));
  std::map<std::string, std::string> golden;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') golden[line.substr(0, line.find(':'))] = line;
  return golden;
}

std::vector<std::string> bad_files() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kBad))
    if (e.path().extension() == ".fap") names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(FapTextBad, EveryFileHasAGoldenErrorAndBack) {
  const auto golden = golden_errors();
  const auto files = bad_files();
  EXPECT_GE(files.size(), 15u);
  for (const auto& f : files) EXPECT_TRUE(golden.count(f)) << f << " has no line in expected-errors.txt";
  for (const auto& [f, msg] : golden)
    EXPECT_TRUE(std::find(files.begin(), files.end(), f) != files.end()) << "no file " << f;
}

class FapTextBadFile : public testing::TestWithParam<std::string> {};

TEST_P(FapTextBadFile, IsRefusedWithTheGoldenMessage) {
  const std::string& name = GetParam();
  const std::string bytes = read_file(kBad / name);
  // bad.NNN.<rule>.fap
  const std::string rule = name.substr(8, name.size() - 8 - 4);
  try {
    read_fap_text(bytes, name);
    FAIL() << name << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule(), rule);
    EXPECT_EQ(e.what(), golden_errors()[name]);
    EXPECT_EQ(e.where().source, name);
    EXPECT_TRUE(e.where().line.has_value());
  }
}

INSTANTIATE_TEST_SUITE_P(Golden, FapTextBadFile, testing::ValuesIn(bad_files()), [](const auto& info) {
  std::string n = info.param.substr(4, 3);
  return "bad" + n;
});

}  // namespace
}  // namespace fapcast
