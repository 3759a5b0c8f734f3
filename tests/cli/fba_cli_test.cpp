// End to end: `fapcast encode` / `fapcast decode` on the real Xface samples (tests/data/xface).
#include "fapcast/codec/fap_text.hpp"
#include "fapcast/fba/fba_quantiser.hpp"
#include "cli/fapcast_command.hpp"
#include "support/run_command.hpp"
#include "support/file_bytes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fapcast::test {
namespace {

namespace fs = std::filesystem;
const fs::path kXface = fs::path(FAPCAST_TEST_DATA) / "xface";

FapSequence read_fap(const fs::path& p) { return read_fap_text(slurp(p), p.string()).sequence; }

struct CliCase {
  std::string sample;
  int quant;
};

class FbaCli : public ::testing::TestWithParam<CliCase> {};

// Every Xface sample encodes and decodes in the standard syntax; each value comes back within
// step/2 (exact at 0). At fap_quant 0 a sample whose head rotation goes beyond +/-1860 AU is refused
// instead, and the message says to use the fapcast profile, which then codes it losslessly.
TEST_P(FbaCli, XfaceSampleRoundTripsThroughTheCommandLine) {
  const auto& [sample, quant] = GetParam();
  const std::string dir = make_temp_dir("fba-cli");
  const fs::path in = kXface / (sample + ".fap");
  const std::string fba = dir + "/" + sample + ".fba", out = dir + "/" + sample + ".fap";
  const auto enc = run_command(fapcast("encode " + in.string() + " -o " + fba + " --quant " + std::to_string(quant) + " --iperiod 10"));
  bool beyond = false;
  for (const auto& f : read_fap(in).frames)
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) beyond |= f.mask.test(n) && std::abs(f.value(n)) > 1860;
  if (quant == 0 && beyond) {
    EXPECT_EQ(enc.exit_code, 1);
    EXPECT_NE(enc.err.find("beyond the standard syntax's codable range +/-1860 at fap_quant 0 (refused, never clipped)"),
              std::string::npos)
        << enc.err;
    EXPECT_NE(enc.err.find("use --profile fapcast to code every value losslessly"), std::string::npos) << enc.err;
    EXPECT_FALSE(fs::exists(fba));
    const auto lossless = run_command(fapcast("encode " + in.string() + " -o " + fba + " --profile fapcast"));
    ASSERT_EQ(lossless.exit_code, 0) << lossless.err;
    EXPECT_NE(lossless.err.find("fapcast profile at fap_quant 0 (lossless)"), std::string::npos) << lossless.err;
    ASSERT_EQ(run_command(fapcast("decode " + fba + " -o " + out)).exit_code, 0);
    EXPECT_EQ(read_fap(out).frames, read_fap(in).frames);
    const auto refused = run_command(fapcast("decode " + fba + " -o " + dir + "/refused.fap --profile standard"));
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_NE(refused.err.find("byte 0: fapcast-profile: a fapcast-profile stream"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(dir + "/refused.fap"));
    return;
  }
  ASSERT_EQ(enc.exit_code, 0) << enc.err;
  ASSERT_LT(fs::file_size(fba), fs::file_size(in));
  const auto dec = run_command(fapcast("decode " + fba + " -o " + out + " --profile standard"));
  ASSERT_EQ(dec.exit_code, 0) << dec.err;
  EXPECT_NE(dec.err.find("standard FBA, fap_quant " + std::to_string(quant)), std::string::npos) << dec.err;
  const FapSequence a = read_fap(in), b = read_fap(out);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  EXPECT_EQ(a.rate, b.rate);
  for (std::size_t k = 0; k < a.frames.size(); ++k) {
    ASSERT_EQ(a.frames[k].mask, b.frames[k].mask) << k;
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
      ASSERT_LE(2 * std::abs(a.frames[k].value(n) - b.frames[k].value(n)), fba_step(n, quant)) << k << " " << n;
    if (quant == 0) {
      EXPECT_EQ(a.frames[k].values, b.frames[k].values);
    }
  }
}

std::vector<CliCase> cases() {
  std::vector<CliCase> out;
  for (const char* s : {"anger", "beg", "disgust", "fear", "happy-for", "hate", "joy", "pride"})
    for (int q : {0, 1, 8}) out.push_back({s, q});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Xface, FbaCli, ::testing::ValuesIn(cases()), [](const auto& info) {
  std::string name = info.param.sample + "_q" + std::to_string(info.param.quant);
  for (char& c : name) if (c == '-') c = '_';
  return name;
});

TEST(FbaCliErrors, BadStreamIsReportedWithByteOffsetAndRule) {
  const std::string dir = make_temp_dir("fba-cli-bad");
  const fs::path bad = fs::path(FAPCAST_TEST_DATA) / "fba" / "bad" / "bad.004.bad-start-code.fba";
  const auto r = run_command(fapcast("decode " + bad.string() + " -o " + dir + "/x.fap"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("byte 397: bad-start-code"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frames lost"), std::string::npos) << r.err;
}

TEST(FbaCliErrors, UncodableValueNamesFrameAndFapAndWritesNothing) {
  const std::string dir = make_temp_dir("fba-cli-range");
  std::string mask(68 * 2, ' ');
  for (int i = 0; i < 68; ++i) mask[static_cast<std::size_t>(2 * i)] = i == 47 ? '1' : '0';
  mask.pop_back();
  std::ofstream(dir + "/big.fap") << "2.1 big 25 2\n" << mask << "\n0 100\n" << mask << "\n1 5000\n";
  const auto r = run_command(fapcast("encode " + dir + "/big.fap -o " + dir + "/big.fba --quant 0"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("frame 1, FAP 48 head_pitch: value 5000"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/big.fba"));
}

TEST(FbaCliErrors, QuantOutOfRangeIsAUsageError) {
  const auto r = run_command(fapcast("encode x.fap -o y.fba --quant 32"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
}

TEST(FbaCliErrors, ArchiveAndIperiodTogetherIsAUsageError) {
  const auto r = run_command(fapcast("encode x.fap -o y.fba --archive --iperiod 10"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
}

}  // namespace
}  // namespace fapcast::test

namespace fapcast::test {
namespace {

TEST(FbaCliArchive, ArchivePresetIsSmallerAndDecodesWithinHalfAStep) {
  const std::string dir = make_temp_dir("fba-cli-archive");
  const std::string in = (fs::path(FAPCAST_TEST_DATA) / "xface" / "joy.fap").string();
  ASSERT_EQ(run_command(fapcast("encode " + in + " -o " + dir + "/default.fba --quant 2 --iperiod 25")).exit_code, 0);
  const auto enc = run_command(fapcast("encode " + in + " -o " + dir + "/archive.fba --quant 2 --archive"));
  ASSERT_EQ(enc.exit_code, 0) << enc.err;
  EXPECT_LT(fs::file_size(dir + "/archive.fba"), fs::file_size(dir + "/default.fba"));
  ASSERT_EQ(run_command(fapcast("decode " + dir + "/archive.fba -o " + dir + "/back.fap")).exit_code, 0);
  const FapSequence a = read_fap(in), b = read_fap(dir + "/back.fap");
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t k = 0; k < a.frames.size(); ++k)
    for (int n = kFirstLowLevelFap; n <= kFapCount; ++n)
      ASSERT_LE(2 * std::abs(a.frames[k].value(n) - b.frames[k].value(n)), fba_step(n, 2)) << k << " " << n;
}

TEST(FbaCliInfo, FapInfoReadsFbaToo) {
  const std::string dir = make_temp_dir("fba-cli-info");
  const std::string in = (fs::path(FAPCAST_TEST_DATA) / "xface" / "joy.fap").string();
  ASSERT_EQ(run_command(fapcast("encode " + in + " -o " + dir + "/joy.fba")).exit_code, 0);
  const auto text = run_command(fapcast("fap info " + in + " --json"));
  const auto fba = run_command(fapcast("fap info " + dir + "/joy.fba --json"));
  ASSERT_EQ(fba.exit_code, 0) << fba.err;
  EXPECT_NE(fba.out.find("\"format\": \"fba\""), std::string::npos) << fba.out;
  // Same frame count and masked FAPs as the text it came from.
  const auto count = [](const std::string& s) { return s.substr(s.find("\"frames\":"), 16); };
  EXPECT_EQ(count(fba.out), count(text.out));
}

}  // namespace
}  // namespace fapcast::test
