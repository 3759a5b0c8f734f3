// Named bad .fba streams (tests/data/fba/bad/bad.NNN.<rule>.fba) and the golden list of what
// the decoder says about each (expected.txt). FAPCAST_WRITE_BAD_FBA=1 regenerates the files
// from encodes of a SYNTHETIC track (and prints the golden lines for review).
#include "arithmetic_coder.hpp"
#include "fba_bits.hpp"
#include "fba_plane.hpp"
#include "fapcast/fba/fba_file.hpp"
#include "fapcast/fba/fba_stream.hpp"
#include "fba/fba_test_support.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>

#include "support/file_bytes.hpp"

namespace fapcast {
namespace {

namespace fs = std::filesystem;
const fs::path kBadDir = fs::path(FAPCAST_TEST_DATA) / "fba" / "bad";
using Bytes = std::vector<std::uint8_t>;

std::string describe(const FbaDecodeReport& report) {
  std::string out;
  for (const auto& e : report.errors) out += (out.empty() ? "" : "; ") + e.message();
  return out;
}

using test::read_bytes;
using test::run_offsets;

void set_bit(Bytes& b, std::size_t byte, std::size_t bit, bool on) {  // bit counted from byte's MSB
  const std::size_t at = byte * 8 + bit;
  const auto mask = static_cast<std::uint8_t>(0x80u >> (at % 8));
  b[at / 8] = static_cast<std::uint8_t>(on ? b[at / 8] | mask : b[at / 8] & ~mask);
}

FbaEncoderOptions untimed_options(FbaProfile profile, int q, int period) {
  FbaEncoderOptions o = test::encoder_options(profile, q, period);
  o.time_codes = false;  // the intra header's bit positions below are fixed
  return o;
}

// A standard stream whose first plane is written by hand after the object start code and a plane
// start code: is_intra 1, FAP object, a frame rate of 25, then `fields`, then the end code.
template <typename Fields>
Bytes handmade(Fields&& fields) {
  FbaBitWriter w;
  w.start_code(kFbaObjectStartCode);
  w.stuff_to_start_code();
  w.start_code(kFbaPlaneStartCode);
  w.put_bit(1);  // is_intra
  w.put(1, 2);   // FAP object
  w.put_bit(1);  // is_frame_rate
  w.put(25, 8);
  w.put(0, 4);
  w.put_bit(0);
  fields(w);
  w.stuff_to_start_code();
  w.start_code(kFbaEndCode);
  return w.bytes();
}

// The bad streams, each derived from a real encode by one change.
std::map<std::string, Bytes> make_bad_streams() {
  std::mt19937_64 rng(7);
  FapMask lips;
  for (int n = 3; n <= 18; ++n) lips.set(n);  // group 2 only: the intra header's bit positions are fixed
  const FapSequence seq{"synthetic", {25, 1}, test::smooth_track(rng, lips, 60, 400)};
  const Bytes good = encode_fba(seq, untimed_options(FbaProfile::kStandard, 1, 25));
  const auto runs = run_offsets(good);  // frames 0, 25, 50
  // Bit positions after run 0's start code (spec/fba.md §3, §4): is_intra 0, fba_object_mask
  // 1-2, is_frame_rate 3, frame_rate 4-11, seconds 12-15, frequency_offset 16, is_time_code 17,
  // skip_frames 18, fap_quant 19-23, group markers and types 24-53, suggested_gender 54,
  // coding_type 55, the range flags 56-59.
  const std::size_t body = runs[0] + 4;
  // The same frames as access units of the frame-at-a-time coder; `edit` may change unit k (and
  // drop it by returning false) before it is appended.
  const auto from_units = [&](auto&& edit) {
    FbaFrameEncoder encoder(untimed_options(FbaProfile::kStandard, 1, 25), {25, 1});
    Bytes units = {0, 0, 1, 0xBA, 0x7F};
    for (std::size_t k = 0; k < seq.frames.size(); ++k) {
      FbaAccessUnit unit;
      if (encoder.encode(seq.frames[k], unit)) break;
      if (edit(k, encoder.last_bits(), unit.bytes)) units.insert(units.end(), unit.bytes.begin(), unit.bytes.end());
    }
    units.insert(units.end(), {0, 0, 1, 0xB1});
    return units;
  };
  std::map<std::string, Bytes> out;
  Bytes b = good;
  b.resize(runs[1] + (runs[2] - runs[1]) / 2);
  out["001.truncated"] = b;
  b = good;
  b.resize(b.size() - 4);
  out["002.missing-end-code"] = b;
  out["003.missing-object-start-code"] = Bytes(good.begin() + 4, good.end());
  b = good;
  b[runs[1] + 3] = 0xB5;
  out["004.bad-start-code"] = b;
  b = good;
  set_bit(b, body, 1, true);
  set_bit(b, body, 2, false);  // fba_object_mask 2: body
  out["005.unsupported-object"] = b;
  b = good;
  set_bit(b, body, 55, true);  // coding_type 1
  out["006.dct-coding-unsupported"] = b;
  b = good;
  for (std::size_t i = 4; i < 12; ++i) set_bit(b, body, i, false);  // frame_rate 0 (seconds are 0)
  out["007.bad-frame-rate"] = b;
  b = good;
  set_bit(b, body, 24, false);  // group 1's marker
  out["008.marker-bit-missing"] = b;
  {
    // A stream rich in zeros (see FbaFile.StuffingPreventsStartCodeEmulation); clear a stuffed 1.
    std::vector<FapFrame> frames(4);
    for (std::size_t k = 0; k < frames.size(); ++k)
      for (int n = 3; n <= 18; ++n) frames[k].set(n, k % 2 == 1 ? 1800 : 0);
    b = encode_fba({"synthetic", {25, 1}, frames}, untimed_options(FbaProfile::kStandard, 0, 100));
    const auto zp = run_offsets(b);
    int run = 0;
    for (std::size_t at = (zp[0] + 4) * 8; at < (b.size() - 4) * 8; ++at) {
      const bool bit = (b[at / 8] >> (7 - at % 8)) & 1;
      if (run == 22) {
        set_bit(b, 0, at, false);
        break;
      }
      run = bit ? 0 : run + 1;
    }
    out["009.stuffing-bit-missing"] = b;
  }
  out["010.predicted-without-intra"] = from_units([](std::size_t k, std::uint64_t, Bytes&) { return k != 0; });
  b = good;
  for (char c : std::string("garbage")) b.push_back(static_cast<std::uint8_t>(c));
  out["011.trailing-bytes"] = b;
  {
    bool done = false;  // the first unit from 6 on with 2+ stuffing bits: make its last one 0
    out["012.bad-stuffing"] = from_units([&](std::size_t k, std::uint64_t bits, Bytes& unit) {
      if (!done && k >= 6 && bits % 8 != 0 && bits % 8 <= 6) {
        unit.back() &= 0xFE;
        done = true;
      }
      return true;
    });
  }
  out["013.bad-time-code"] = handmade([](FbaBitWriter& w) {
    w.put_bit(1);  // is_time_code
    w.put(0, 5);
    w.put(61, 6);  // minutes 61
    w.put_bit(1);
    w.put(0, 6);
    w.put_bit(0);
  });
  out["014.skip-too-long"] = handmade([](FbaBitWriter& w) {
    w.put_bit(0);
    w.put_bit(1);  // skip_frames: 18 counts of 15 = 270 > 255
    for (int i = 0; i < 18; ++i) w.put(15, 4);
    w.put(0, 4);
  });
  b = good;
  b.erase(b.begin() + 4);  // the next_start_code() byte between the object and the plane start code
  out["015.bad-stuffing"] = b;
  {
    Bytes fapcast = encode_fba(seq, untimed_options(FbaProfile::kFapcast, 0, 25));
    const auto fr = run_offsets(fapcast);
    fapcast.erase(fapcast.begin() + static_cast<std::ptrdiff_t>(fr[1]), fapcast.begin() + static_cast<std::ptrdiff_t>(fr[2]));
    out["016.bad-frame-number"] = fapcast;  // a whole run gone: frames 25..49 counted lost
    Bytes later = encode_fba(seq, untimed_options(FbaProfile::kFapcast, 0, 25));
    later[11] = 2;
    out["017.bad-profile-version"] = later;
  }
  {
    // A P plane that takes viseme_select1 from 14 to 15: coded by hand after a real intra unit.
    FapFrame intra;
    intra.mask.set(kVisemeFap);
    intra.viseme = {14, 0, 63, false};
    FbaFrameEncoder encoder(untimed_options(FbaProfile::kStandard, 1, 25), {25, 1});
    FbaAccessUnit unit;
    encoder.encode(intra, unit);
    Bytes stream = {0, 0, 1, 0xBA, 0x7F};
    stream.insert(stream.end(), unit.bytes.begin(), unit.bytes.end());
    FbaBitWriter w;
    w.start_code(kFbaPlaneStartCode);
    w.put_bit(0);  // P
    w.put(1, 2);
    w.put_bit(0);  // no skip
    {
      ArithmeticEncoder ac(w);
      FrequencyModel select(29), blend(127);
      ac.encode(14 + 1, select);  // select1 + 1
      ac.encode(14, select);      // select2 unchanged
      ac.encode(63, blend);       // blend unchanged
      ac.flush();
    }
    w.put_bit(0);  // viseme_def
    w.stuff_to_start_code();
    stream.insert(stream.end(), w.bytes().begin(), w.bytes().end());
    stream.insert(stream.end(), {0, 0, 1, 0xB1});
    out["018.viseme-range"] = stream;
  }
  {
    // A fapcast-profile intra header with a reference coefficient of 100 sixteenths (at most 64).
    FapFrame f;
    f.set(6, 10).set(7, 10);
    detail::FapcastIntraHeader h;
    h.reference[6] = 6;  // FAP 7 from FAP 6
    h.coefficient[6] = 100;
    FbaCodingState state;
    state.profile = FbaProfile::kFapcast;
    FbaBitWriter w(FbaStuffing::kContinuous);
    w.start_code(kFbaUserDataStartCode);
    for (const std::uint8_t c : fba_fapcast_opening().subspan(4)) w.put(c, 8);
    w.start_code(kFbaPlaneStartCode);
    detail::write_plane(state, f, nullptr, &h, 0, w);
    w.stuff_to_start_code();
    w.start_code(kFbaEndCode);
    out["019.bad-field"] = w.bytes();
  }
  return out;
}

TEST(FbaBadStreams, EachGivesItsGoldenErrors) {
  if (std::getenv("FAPCAST_WRITE_BAD_FBA")) {
    fs::create_directories(kBadDir);
    for (const auto& entry : fs::directory_iterator(kBadDir))
      if (entry.path().extension() == ".fba") fs::remove(entry.path());
    for (const auto& [name, bytes] : make_bad_streams()) {
      std::ofstream(kBadDir / ("bad." + name + ".fba"), std::ios::binary)
          .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
      std::cout << "bad." << name << ".fba\t" << describe(decode_fba(bytes).report) << "\n";
    }
  }
  std::map<std::string, std::string> golden;
  std::ifstream list(kBadDir / "expected.txt");
  ASSERT_TRUE(list) << "missing " << (kBadDir / "expected.txt");
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << line;
    golden[line.substr(0, tab)] = line.substr(tab + 1);
  }
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(kBadDir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".fba") continue;
    ++files;
    SCOPED_TRACE(name);
    const auto result = decode_fba(read_bytes(entry.path()));
    ASSERT_FALSE(result.report.ok());
    ASSERT_TRUE(golden.count(name)) << "no golden line";
    EXPECT_EQ(describe(result.report), golden[name]);
    // The rule in the file name is the first error's rule.
    const std::string rule = name.substr(8, name.size() - 8 - 4);
    const std::string first = result.report.errors.front().message();
    EXPECT_EQ(first.substr(first.find(": ") + 2, rule.size() + 1), rule + ":") << first;
  }
  EXPECT_EQ(files, golden.size());
  EXPECT_GE(files, 19u);
}

// The files still match what the encoder makes today (so the golden list stays meaningful).
TEST(FbaBadStreams, FilesAreReproducibleFromTheirRecipe) {
  for (const auto& [name, bytes] : make_bad_streams()) {
    EXPECT_EQ(read_bytes(kBadDir / ("bad." + name + ".fba")), bytes) << name;
  }
}

}  // namespace
}  // namespace fapcast
