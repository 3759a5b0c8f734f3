// MOCHA-TIMIT EMA: the real fsew0_001.ema (headerless MOCHAtools rows) against its columns read
// independently, and the EST Track forms (ASCII, binary in both byte orders, MOCHA's own channel
// layout) written from the same numbers and read back.
#include "fapcast/corpus/ema.hpp"
#include "fapcast/core/input_error.hpp"
#include "corpus/corpus_test_support.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <sstream>

namespace fapcast {
namespace {

using test::file_bytes;

std::filesystem::path fsew0_path() { return std::filesystem::path(FAPCAST_TEST_DATA) / "mocha/fsew0_001.ema"; }

// fsew0_001.ema's rows as numbers, parsed with a stream (not the reader's field splitter).
std::vector<std::vector<double>> fsew0_rows() {
  std::istringstream in(file_bytes(fsew0_path()));
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::vector<double> row;
    double v = 0;
    while (cells >> v) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

// The 1-based columns of each coil's x and y in the MOCHAtools rows, from the data's README.
struct CoilColumns {
  const char* coil;
  int x, y;
};
constexpr CoilColumns kReadmeColumns[] = {{"li", 4, 9},   {"ul", 5, 10},  {"ll", 6, 11},  {"tt", 7, 12}, {"tb", 13, 18},
                                          {"td", 14, 19}, {"v", 15, 20},  {"ui", 3, 8},   {"bn", 17, 22}};

double stddev(const Eigen::VectorXd& v) { return std::sqrt((v.array() - v.mean()).square().mean()); }

std::string error_of(const std::string& bytes, const std::string& name = "t.ema") {
  try {
    (void)read_ema(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "<accepted>";
}

TEST(Ema, ReadsTheRealMochaFileAsItsColumnsSay) {
  const MarkerFrames<Millimetres> m = read_ema(file_bytes(fsew0_path()), "fsew0_001.ema");
  const auto rows = fsew0_rows();
  ASSERT_EQ(rows.size(), 966u);
  ASSERT_EQ(m.frame_count(), 966);
  EXPECT_EQ(m.frame_rate_hz, 500.0);
  EXPECT_EQ(m.first_frame, 0);
  EXPECT_EQ(m.labels, (std::vector<std::string>{"li", "ul", "ll", "tt", "tb", "td", "v", "ui", "bn"}));
  for (const CoilColumns& c : kReadmeColumns) {
    const auto m_index = m.find(c.coil);
    ASSERT_TRUE(m_index) << c.coil;
    for (std::size_t k = 0; k < rows.size(); k += 37) {
      ASSERT_EQ(rows[k].size(), 22u);
      EXPECT_NEAR(m.at(*m_index, static_cast<Eigen::Index>(k)).x(), rows[k][c.x - 1] / 100, 1e-12) << c.coil << " " << k;
      EXPECT_NEAR(m.at(*m_index, static_cast<Eigen::Index>(k)).y(), rows[k][c.y - 1] / 100, 1e-12) << c.coil << " " << k;
      EXPECT_EQ(m.at(*m_index, static_cast<Eigen::Index>(k)).z(), 0.0);
    }
  }
}

TEST(Ema, RealFileHasAStillUpperIncisorAndPlausibleLips) {
  const MarkerFrames<Millimetres> m = read_ema(file_bytes(fsew0_path()), "fsew0_001.ema");
  const auto coil_y = [&](const char* coil) { return Eigen::VectorXd(m.positions.row(3 * *m.find(coil) + 1)); };
  const auto coil_x = [&](const char* coil) { return Eigen::VectorXd(m.positions.row(3 * *m.find(coil))); };
  // The upper incisor is the fixed reference coil (the origin): it moves least of all coils.
  const double ui = std::max(stddev(coil_x("ui")), stddev(coil_y("ui")));
  EXPECT_LT(ui, 0.3);
  for (const char* coil : {"li", "ul", "ll", "tt", "tb", "td"}) EXPECT_GT(stddev(coil_y(coil)), 2 * ui) << coil;
  // The lips sit in front of the incisor (negative x); the lower lip below the upper one by a
  // vertical separation of a few mm to a few cm, opening and closing by several mm.
  EXPECT_LT(coil_x("ul").maxCoeff(), 0.0);
  EXPECT_LT(coil_x("ll").maxCoeff(), 0.0);
  const Eigen::VectorXd separation = coil_y("ul") - coil_y("ll");
  EXPECT_GT(separation.minCoeff(), 3.0);
  EXPECT_LT(separation.maxCoeff(), 40.0);
  EXPECT_GT(separation.maxCoeff() - separation.minCoeff(), 5.0);
  EXPECT_LT(separation.maxCoeff() - separation.minCoeff(), 25.0);
}

TEST(Ema, EstAsciiRoundTripKeepsTheNumbers) {
  const MarkerFrames<Millimetres> m = read_ema(file_bytes(fsew0_path()), "fsew0_001.ema");
  const std::string est = write_ema_est(m, EstEncoding::ascii);
  ASSERT_TRUE(est.starts_with("EST_File Track\nDataType ascii\n"));
  const MarkerFrames<Millimetres> back = read_ema(est, "fsew0.est");
  EXPECT_EQ(back.labels, m.labels);
  EXPECT_EQ(back.frame_rate_hz, 500.0);
  EXPECT_EQ(back.first_frame, 0);
  ASSERT_EQ(back.positions.cols(), m.positions.cols());
  EXPECT_LT((back.positions - m.positions).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Ema, EstBinaryRoundTripInBothByteOrders) {
  const MarkerFrames<Millimetres> m = read_ema(file_bytes(fsew0_path()), "fsew0_001.ema");
  for (const EstEncoding e : {EstEncoding::binary_little_endian, EstEncoding::binary_big_endian}) {
    const std::string est = write_ema_est(m, e);
    const bool big = e == EstEncoding::binary_big_endian;
    ASSERT_NE(est.find(big ? "\nByteOrder 10\n" : "\nByteOrder 01\n"), std::string::npos);
    // Frame 0's break flag (valid: 1.0f = 0x3f800000) in the stated order, 4 bytes after the time.
    const std::size_t data = est.find("EST_Header_End\n") + 15;
    EXPECT_EQ(static_cast<unsigned char>(est[data + (big ? 4 : 7)]), 0x3f);
    EXPECT_EQ(static_cast<unsigned char>(est[data + (big ? 5 : 6)]), 0x80);
    EXPECT_EQ(est.size() - data, 966u * 4 * (2 + 18));
    const MarkerFrames<Millimetres> back = read_ema(est, "fsew0.est");
    EXPECT_EQ(back.labels, m.labels);
    EXPECT_EQ(back.frame_rate_hz, 500.0);
    ASSERT_EQ(back.positions.cols(), m.positions.cols());
    // float32 keeps 24 bits: |v| < 120 mm is within 120 / 2^24 mm.
    EXPECT_LT((back.positions - m.positions).cwiseAbs().maxCoeff(), 1e-5);
    if (big) {
      EXPECT_EQ(back, read_ema(write_ema_est(m, EstEncoding::binary_little_endian), "le.est"));
    }
  }
}

// MOCHA-TIMIT's own binary header (20 channels with the undocumented pair "****", as the corpus
// files carry it), written here around fsew0_001's 20 columns: the coils come out as the
// headerless reading of the same numbers.
TEST(Ema, MochaBinaryChannelLayoutAgreesWithTheHeaderlessColumns) {
  const auto rows = fsew0_rows();
  std::string est =
      "EST_File Track\nDataType binary\nNumFrames 966\nByteOrder 01\nNumChannels 20\nEqualSpace 1\n"
      "BreaksPresent true\nCommentChar ;\n\n";
  const char* names[] = {"ui_x", "li_x", "ul_x", "ll_x", "tt_x", "ui_y", "li_y", "ul_y", "ll_y", "tt_y",
                         "tb_x", "td_x", "v_x ", "****", "bn_x", "tb_y", "td_y", "v_y ", "****", "bn_y"};
  for (int c = 0; c < 20; ++c) est += "Channel_" + std::to_string(c) + " " + names[c] + "\n";
  est += "EST_Header_End\n";
  for (const auto& row : rows) {
    for (const double v : row) {
      const auto bits = std::bit_cast<std::uint32_t>(static_cast<float>(v));
      for (int i = 0; i < 4; ++i) est += static_cast<char>((bits >> (8 * i)) & 0xff);
    }
  }
  const MarkerFrames<Millimetres> bin = read_ema(est, "fsew0_bin.ema");
  const MarkerFrames<Millimetres> text = read_ema(file_bytes(fsew0_path()), "fsew0_001.ema");
  EXPECT_EQ(bin.labels, text.labels);
  EXPECT_EQ(bin.frame_rate_hz, 500.0);
  ASSERT_EQ(bin.positions.cols(), 966);
  EXPECT_LT((bin.positions - text.positions).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(Ema, BreakFramesAreMissingAndAStartTimeNumbersTheFirstFrame) {
  const std::string est =
      "EST_File Track\nDataType ascii\nNumFrames 4\nNumChannels 3\nEqualSpace 1\nBreaksPresent true\n"
      "Channel_0 ll_y\nChannel_1 extra\nChannel_2 ll_x\nEST_Header_End\n"
      "1.000000\t1 \t-200 7 -1000\n1.010000\t0 \t0 0 0\n1.020000\t1 \t-250 8 -1100\n1.030000\t1 \t-300 9 -1200\n";
  const MarkerFrames<Millimetres> m = read_ema(est, "b.ema");
  EXPECT_EQ(m.labels, std::vector<std::string>{"ll"});
  EXPECT_EQ(m.frame_rate_hz, 100.0);
  EXPECT_EQ(m.first_frame, 100);
  ASSERT_EQ(m.frame_count(), 4);
  EXPECT_EQ(m.at(0, 0), Eigen::Vector3d(-10, -2, 0));
  EXPECT_FALSE(m.present(0, 1));
  EXPECT_EQ(m.at(0, 3), Eigen::Vector3d(-12, -3, 0));
  // A written break frame reads back as a break.
  const MarkerFrames<Millimetres> back = read_ema(write_ema_est(m, EstEncoding::binary_big_endian), "b2.ema");
  EXPECT_EQ(back, m);
}

TEST(Ema, FrameShiftGivesTheRateOfASingleFrame) {
  const std::string est =
      "EST_File Track\nDataType ascii\nNumFrames 1\nNumChannels 2\nFrameShift 0.005\n"
      "Channel_0 tt_x\nChannel_1 tt_y\nEST_Header_End\n0.5 100 200\n";
  const MarkerFrames<Millimetres> m = read_ema(est, "s.ema");
  EXPECT_EQ(m.frame_rate_hz, 200.0);
  EXPECT_EQ(m.first_frame, 100);
  EXPECT_EQ(m.at(0, 0), Eigen::Vector3d(1, 2, 0));
}

// The fuzz seeds: fsew0_001's first 12 frames headerless, and in MOCHA's EST header as EST
// writes ASCII ("%f\t1 \t%f ...") and binary in both byte orders, frame 5 flagged a break.
TEST(Ema, FuzzSeedsAreTheSameTwelveFramesInEachForm) {
  const auto seeds = std::filesystem::path(FAPCAST_SOURCE_DIR) / "tests/fuzz/corpus/ema_fuzz";
  const MarkerFrames<Millimetres> head = read_ema(file_bytes(seeds / "fsew0_head.ema"), "fsew0_head.ema");
  ASSERT_EQ(head.frame_count(), 12);
  EXPECT_EQ(head.frame_rate_hz, 500.0);
  for (const char* name : {"fsew0_est_ascii.ema", "fsew0_est_le.ema", "fsew0_est_be.ema"}) {
    const MarkerFrames<Millimetres> m = read_ema(file_bytes(seeds / name), name);
    EXPECT_EQ(m.labels, head.labels) << name;
    EXPECT_EQ(m.frame_rate_hz, 500.0) << name;
    ASSERT_EQ(m.frame_count(), 12) << name;
    for (Eigen::Index k = 0; k < 12; ++k) {
      for (Eigen::Index c = 0; c < m.marker_count(); ++c) {
        EXPECT_EQ(m.present(c, k), k != 5) << name << " frame " << k;
        if (k != 5) {
          EXPECT_LT((m.at(c, k) - head.at(c, k)).norm(), 1e-5) << name << " frame " << k;
        }
      }
    }
  }
}

TEST(Ema, RefusesWhatItCannotReadWithLocatedRules) {
  const std::string head = "EST_File Track\nDataType ascii\nNumFrames 2\nNumChannels 2\nBreaksPresent true\n";
  const std::string names = "Channel_0 ul_x\nChannel_1 ul_y\nEST_Header_End\n";
  EXPECT_EQ(error_of(head + names + "0 1 1 2\n0.002 1 1\n"),
            "t.ema:10: ema-fields: a frame has 4 fields (time, break flag, 2 channels); this row has 3");
  EXPECT_EQ(error_of(head + names + "0 1 1 2\n0.002 1 1 inf\n"), "t.ema:10: ema-bad-number: \"inf\" is not a finite number");
  EXPECT_EQ(error_of(head + names + "0 1 1 2\n"), "t.ema:3: ema-frame-count: NumFrames is 2 but 1 frames follow");
  EXPECT_EQ(error_of(head + "Channel_0 ul_x\nChannel_1 xx\nEST_Header_End\n0 1 1 2\n0.002 1 1 2\n"),
            "t.ema:4: ema-channel-names: coil ul has an x channel but no y");
  EXPECT_EQ(error_of(head + "Channel_0 a\nEST_Header_End\n"),
            "t.ema:4: ema-no-coils: no channel pair <coil>_x, <coil>_y for a MOCHA coil (li ul ll tt tb td v ui bn)");
  EXPECT_EQ(error_of(head + names), "t.ema:3: ema-frame-count: NumFrames is 2 but 0 frames follow");
  EXPECT_EQ(error_of(head + "Channel_0 ul_x\n"), "t.ema:7: ema-no-header-end: the header has no EST_Header_End line");
  EXPECT_EQ(error_of(head + names + "0 1 1 2\n0.002 2 1 2\n"), "t.ema:10: ema-bad-flag: the break flag \"2\" is not 0 or 1");
  EXPECT_EQ(error_of(head + names + "0 1 1 2\n0 1 1 2\n"),
            "t.ema:10: ema-time-step: times do not increase (first 0 s, last 0 s)");
  EXPECT_EQ(error_of(head + names + "0 1 1 2\n0.002 1 1 2e8\n"), "t.ema:10: ema-bad-number: \"2e8\" is beyond +-1e8 (1 km)");
  EXPECT_EQ(error_of(head + names + "2e6 1 1 2\n2000000.002 1 1 2\n"),
            "t.ema:9: ema-start-time: the first time 2e+06 s is outside 0-1e+06 s");
  EXPECT_EQ(error_of("0 1 2\n"),
            "t.ema:1: ema-fields: a frame has 22 fields (time, break flag, 20 channels); this row has 3");
}

}  // namespace
}  // namespace fapcast
