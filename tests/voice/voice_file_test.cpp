#include "fapcast/voice/voice_file.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

#include "fapcast/core/crc32.hpp"
#include "fapcast/core/input_error.hpp"
#include "fapcast/core/file_io.hpp"
#include "support/bad_inputs.hpp"

namespace fapcast {
namespace {

namespace vs = voice_section;
const std::filesystem::path kData = std::filesystem::path(FAPCAST_TEST_DATA) / "voice";

TEST(Crc32, MatchesTheStandardCheckValueAndChains) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32(std::as_bytes(std::span(s))), 0xCBF43926u);
  EXPECT_EQ(crc32({}), 0u);
  const auto all = std::as_bytes(std::span(s));
  EXPECT_EQ(crc32(all.subspan(4), crc32(all.first(4))), 0xCBF43926u);
  EXPECT_EQ(crc32({}, 0x12345678u), 0x12345678u);  // an empty piece keeps the running value
}

// The bit-at-a-time definition (reflected 0xEDB88320), to check the library's wide paths against.
std::uint32_t crc32_bitwise(std::span<const std::byte> bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::byte b : bytes) {
    c ^= static_cast<std::uint32_t>(b);
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

TEST(Crc32, LongBuffersAtAnyAlignmentMatchTheDefinition) {
  std::vector<std::byte> b(1 << 20);
  std::uint32_t x = 0x9E3779B9u;
  for (std::byte& v : b) {
    x ^= x << 13, x ^= x >> 17, x ^= x << 5;
    v = static_cast<std::byte>(x >> 24);
  }
  const std::span<const std::byte> all(b);
  const std::uint32_t whole = crc32_bitwise(all);
  EXPECT_EQ(crc32(all), whole);
  for (std::size_t cut : {1u, 7u, 63u, 4097u, 524'289u})  // the vector loops entered off alignment
    EXPECT_EQ(crc32(all.subspan(cut), crc32(all.first(cut))), whole) << "split at " << cut;
  EXPECT_EQ(crc32(all.subspan(3, 1000)), crc32_bitwise(all.subspan(3, 1000)));
}

VoiceProvenance tiny_provenance() {
  VoiceProvenance p;
  p.corpus = "tests/data/voice (hand-made, 3 frames)";
  p.target_face = "two-vertex test face";
  p.seed = 7;
  p.synthetic = true;
  p.build_time_utc = "2026-11-22T04:00:00Z";
  p.tool_version = "0.1.0";
  p.parameters = {{"k", 2}, {"lambda", 0.001}, {"r_squared", 0.5}};
  return p;
}

// A complete, tiny voice: D = 6 (2 vertices), k = 2, m = 2 centres of d = 3, 3 frames.
// `skip` leaves one section out (for the missing-section case).
std::string tiny_voice(SectionId skip = SectionId{"----"}) {
  VoiceFileWriter w;
  auto add = [&](SectionId id, auto matrix) {
    if (!(id == skip)) w.add_matrix(id, matrix);
  };
  if (!(vs::kProvenance == skip)) w.add_provenance(tiny_provenance());
  add(vs::kPcaMean, RowMajorMatrixXf{{0.f, 1.f, 2.f, 3.f, 4.f, 5.f}});
  add(vs::kPcaComponents, RowMajorMatrixXf{{1.f, 0.f, 0.f, 0.f, 0.f, 0.f}, {0.f, 1.f, 0.f, 0.f, 0.f, 0.f}});
  add(vs::kPcaVariances, RowMajorMatrixXf{{2.f, 1.f}});
  add(vs::kFrameCoefficients, RowMajorMatrixXf{{0.f, 1.f}, {1.f, 0.f}, {-1.f, -1.f}});
  add(vs::kRbfCentres, RowMajorMatrixXd{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
  add(vs::kRbfWeights, RowMajorMatrixXf(RowMajorMatrixXf::Constant(2, 6, 0.5f)));
  add(vs::kRbfOffset, RowMajorMatrixXf(RowMajorMatrixXf::Zero(1, 6)));
  add(vs::kRbfScalars, RowMajorMatrixXd{{0.5, 0.001}});
  if (!(vs::kPhoneGraph == skip)) {
    const std::string graph = "opaque phone graph bytes";
    w.add(vs::kPhoneGraph, ElementType::kBytes, 1, graph.size(), std::as_bytes(std::span(graph)));
  }
  return w.bytes();
}

// Little-endian field pokes and the checksums recomputed after them ("resealed"), so a test can
// break one rule behind a valid header and table.
template <class T>
void poke(std::string& b, std::size_t at, T v) { std::memcpy(b.data() + at, &v, sizeof v); }
template <class T>
T peek(const std::string& b, std::size_t at) { T v; std::memcpy(&v, b.data() + at, sizeof v); return v; }
std::size_t entry(int i) { return 64 + 48 * static_cast<std::size_t>(i); }
void reseal(std::string& b) {
  const auto all = std::as_bytes(std::span(b));
  const std::uint32_t count = peek<std::uint32_t>(b, 12);
  const std::size_t table = std::min<std::size_t>(48 * static_cast<std::size_t>(count), b.size() - 64);
  poke<std::uint32_t>(b, 24, crc32(all.subspan(64, table)));
  poke<std::uint32_t>(b, 28, crc32(all.first(28)));
}

// Opens bytes the way a user's file is opened: written to disk, then open_voice (mmap).
std::string refusal(const std::filesystem::path& file) {
  try {
    (void)open_voice(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(VoiceFile, RoundTripsThroughAMappedFile) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "fapcast_tiny_voice.fapv";
  write_file_atomically(file, tiny_voice());
  const VoiceFileView v = open_voice(file);
  EXPECT_EQ(v.provenance(), tiny_provenance());
  EXPECT_EQ(v.sections().size(), 10u);
  for (const SectionInfo& s : v.sections()) EXPECT_EQ(s.offset % 64, 0u) << s.id.str();
  EXPECT_EQ(v.matrix_f32(vs::kPcaMean), (RowMajorMatrixXf{{0.f, 1.f, 2.f, 3.f, 4.f, 5.f}}));
  EXPECT_EQ(v.matrix_f32(vs::kFrameCoefficients)(2, 1), -1.f);
  EXPECT_EQ(v.matrix_f64(vs::kRbfCentres)(1, 0), 1.0);
  EXPECT_EQ(v.matrix_f64(vs::kRbfScalars)(0, 1), 0.001);
  const auto graph = v.bytes(vs::kPhoneGraph);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(graph.data()), graph.size()), "opaque phone graph bytes");
  EXPECT_THROW((void)v.matrix_f64(vs::kPcaMean), InputError);  // wrong element type
  // The committed fuzz seed is this very file: the writer's bytes are stable.
  const std::filesystem::path seed_file =
      std::filesystem::path(FAPCAST_SOURCE_DIR) / "tests/fuzz/corpus/voice_file_fuzz/tiny.fapv";
  if (std::getenv("FAPCAST_REGENERATE") != nullptr) write_file_atomically(seed_file, tiny_voice());
  const std::string seed = read_file(std::filesystem::path(FAPCAST_SOURCE_DIR) /
                                                "tests/fuzz/corpus/voice_file_fuzz/tiny.fapv");
  EXPECT_EQ(seed, tiny_voice()) << "regenerate with FAPCAST_REGENERATE=1";
  std::filesystem::remove(file);
}

TEST(VoiceFile, WriterRefusesInconsistentSections) {
  VoiceFileWriter w;
  const std::string four = "abcd";
  EXPECT_THROW(w.add(vs::kPhoneGraph, ElementType::kFloat32, 1, 2, std::as_bytes(std::span(four))),
               std::invalid_argument);
  w.add(vs::kPhoneGraph, ElementType::kBytes, 1, 4, std::as_bytes(std::span(four)));
  EXPECT_THROW(w.add(vs::kPhoneGraph, ElementType::kBytes, 1, 4, std::as_bytes(std::span(four))),
               std::invalid_argument);
  EXPECT_THROW(VoiceFileWriter{}.bytes(), std::invalid_argument);
}

// ---- named bad voices: tests/data/voice/bad/bad.NNN.<rule>[.<section>].fapv ----

struct BadVoice {
  std::string name;                         // file name
  std::function<std::string()> make;        // its bytes, from the tiny voice
};

std::vector<BadVoice> bad_voices() {
  std::vector<BadVoice> out;
  auto from_tiny = [](std::function<void(std::string&)> edit) {
    return [edit] { std::string b = tiny_voice(); edit(b); return b; };
  };
  out.push_back({"bad.001.truncated-header.fapv", from_tiny([](std::string& b) { b.resize(40); })});
  out.push_back({"bad.002.bad-magic.fapv", from_tiny([](std::string& b) { b[3] = 'X'; })});
  out.push_back({"bad.003.unsupported-version.fapv", from_tiny([](std::string& b) { poke<std::uint32_t>(b, 8, 2); reseal(b); })});
  out.push_back({"bad.004.header-checksum.fapv", from_tiny([](std::string& b) { b[16] ^= 0x01; })});
  out.push_back({"bad.005.truncated.fapv", from_tiny([](std::string& b) { b.resize(b.size() - 10); })});
  out.push_back({"bad.006.trailing-bytes.fapv", from_tiny([](std::string& b) { b.append(64, '\0'); })});
  out.push_back({"bad.007.section-count.fapv", from_tiny([](std::string& b) { poke<std::uint32_t>(b, 12, 0); reseal(b); })});
  out.push_back({"bad.008.table-out-of-bounds.fapv", from_tiny([](std::string& b) { poke<std::uint32_t>(b, 12, 64); reseal(b); })});
  out.push_back({"bad.009.table-checksum.fapv", from_tiny([](std::string& b) { b[entry(1) + 8] ^= 0x04; })});
  out.push_back({"bad.010.unknown-element-type.fapv", from_tiny([](std::string& b) { poke<std::uint16_t>(b, entry(2) + 4, 9); reseal(b); })});
  out.push_back({"bad.011.section-shape.fapv", from_tiny([](std::string& b) { poke<std::uint64_t>(b, entry(1) + 8, 2); reseal(b); })});
  out.push_back({"bad.012.section-misaligned.fapv", from_tiny([](std::string& b) { poke<std::uint64_t>(b, entry(3) + 24, peek<std::uint64_t>(b, entry(3) + 24) + 4); reseal(b); })});
  out.push_back({"bad.013.section-out-of-bounds.fapv", from_tiny([](std::string& b) { poke<std::uint64_t>(b, entry(9) + 24, (b.size() / 64 + 2) * 64); reseal(b); })});
  out.push_back({"bad.014.section-out-of-bounds.huge-size.fapv", from_tiny([](std::string& b) {
                   poke<std::uint64_t>(b, entry(9) + 16, 0xFFFFFFFFFFFFFFF0ull);  // cols
                   poke<std::uint64_t>(b, entry(9) + 32, 0xFFFFFFFFFFFFFFF0ull);  // size
                   reseal(b); })});
  out.push_back({"bad.015.section-overlap.fapv", from_tiny([](std::string& b) { poke<std::uint64_t>(b, entry(2) + 24, peek<std::uint64_t>(b, entry(1) + 24)); reseal(b); })});
  out.push_back({"bad.016.duplicate-section.fapv", from_tiny([](std::string& b) { std::memcpy(b.data() + entry(5), "PMEA", 4); reseal(b); })});
  const char* ids[] = {"PROV", "PMEA", "PCOM", "PVAR", "FCOE", "RCEN", "RWEI", "ROFF", "RPAR", "GRPH"};
  for (int i = 0; i < 10; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "bad.%03d.section-checksum.%s.fapv", 17 + i, ids[i]);
    out.push_back({name, from_tiny([i](std::string& b) {
                     const auto at = peek<std::uint64_t>(b, entry(i) + 24);
                     b[at + peek<std::uint64_t>(b, entry(i) + 32) / 2] ^= 0x10;  // one bit, mid-section
                   })});
  }
  out.push_back({"bad.027.missing-section.GRPH.fapv", [] { return tiny_voice(vs::kPhoneGraph); }});
  out.push_back({"bad.028.section-shape.PCOM.fapv", [] {
                   std::string b = tiny_voice();
                   poke<std::uint64_t>(b, entry(2) + 8, 3);  // 3 x 6 floats is not 2 x 6 ...
                   poke<std::uint64_t>(b, entry(2) + 16, 4); // ... but 3 x 4 is 48 bytes as well
                   reseal(b);
                   return b; }});
  out.push_back({"bad.029.provenance-json.fapv", [] {
                   std::string b = tiny_voice();
                   const auto at = peek<std::uint64_t>(b, entry(0) + 24);
                   b[at] = '[';  // "{" -> "[": no longer an object (nor valid JSON)
                   poke<std::uint32_t>(b, entry(0) + 40, crc32(std::as_bytes(std::span(b)).subspan(at, peek<std::uint64_t>(b, entry(0) + 32))));
                   reseal(b);
                   return b; }});
  return out;
}

// The golden list: "<file>: <message without the directory>" per line.
std::map<std::string, std::string> golden() { return test::golden_lines(kData / "bad" / "EXPECTED.txt"); }

class BadVoiceFile : public ::testing::TestWithParam<BadVoice> {};

TEST_P(BadVoiceFile, IsRefusedWithTheGoldenMessage) {
  const BadVoice& bad = GetParam();
  const std::filesystem::path file = kData / "bad" / bad.name;
  if (std::getenv("FAPCAST_REGENERATE") != nullptr) {
    write_file_atomically(file, bad.make());
    std::ofstream(kData / "bad" / "EXPECTED.txt", std::ios::app)
        << refusal(file).substr((kData / "bad").string().size() + 1) << "\n";
    return;
  }
  // The committed file is exactly what the recipe makes (so its name tells the truth) ...
  ASSERT_EQ(read_file(file), bad.make()) << bad.name << " is stale: regenerate";
  // ... and is refused, naming the file and the rule, with the golden message.
  const std::string message = refusal(file);
  const std::string rule = bad.name.substr(8, bad.name.find('.', 8) - 8);
  EXPECT_NE(message.find(file.string() + ": byte "), std::string::npos) << message;
  EXPECT_NE(message.find(": " + rule + ": "), std::string::npos) << message;
  const auto expected = golden();
  ASSERT_TRUE(expected.count(bad.name)) << "no golden line for " << bad.name;
  EXPECT_EQ(message.substr((kData / "bad").string().size() + 1), expected.at(bad.name));
}

INSTANTIATE_TEST_SUITE_P(Named, BadVoiceFile, ::testing::ValuesIn(bad_voices()),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(VoiceFile, EveryPrefixAndEverySingleBitFlipIsRefusedNotCrashed) {
  const std::string good = tiny_voice();
  std::vector<std::uint64_t> aligned((good.size() + 7) / 8 + 1);
  auto attempt = [&](std::string_view b) {
    std::memcpy(aligned.data(), b.data(), b.size());
    try {
      const VoiceFileView v = VoiceFileView::over_bytes(
          std::span(reinterpret_cast<const std::byte*>(aligned.data()), b.size()), "<mutant>");
      check_voice_sections(v);
      (void)v.provenance();
      return true;
    } catch (const InputError&) {
      return false;
    }
  };
  EXPECT_TRUE(attempt(good));
  for (std::size_t n = 0; n < good.size(); ++n) EXPECT_FALSE(attempt(std::string_view(good).substr(0, n))) << n;
  // Every bit the checksums cover is caught; only the zero padding between sections is not
  // covered (and carries nothing).
  std::size_t accepted = 0;
  for (std::size_t i = 0; i < good.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      std::string m = good;
      m[i] = static_cast<char>(m[i] ^ (1 << bit));
      accepted += attempt(m) ? 1 : 0;
    }
  }
  std::memcpy(aligned.data(), good.data(), good.size());
  const VoiceFileView v = VoiceFileView::over_bytes(
      std::span(reinterpret_cast<const std::byte*>(aligned.data()), good.size()), "<good>");
  std::size_t covered = 64 + 48 * v.sections().size() - 32;  // header fields before the reserved tail
  for (const SectionInfo& s : v.sections()) covered += s.size;
  EXPECT_EQ(accepted, 8 * (good.size() - covered));
}

TEST(VoiceFile, RefusesWhatCannotBeOpened) {
  EXPECT_THROW((void)VoiceFileView::open(kData / "does-not-exist.fapv"), std::runtime_error);
  EXPECT_THROW((void)VoiceFileView::open(kData), std::runtime_error);  // a directory
}

}  // namespace
}  // namespace fapcast
