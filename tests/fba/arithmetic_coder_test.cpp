// The arithmetic coder and the bit layer it rides on: mirrored round trips, and segment ends
// counted in consumed bits even when a stuffed bit falls inside the decoder's look-ahead.
#include "arithmetic_coder.hpp"
#include "fapcast/fba/fba_errc.hpp"
#include "fba/fba_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace fapcast {
namespace {

class FbaSegments : public testing::TestWithParam<FbaStuffing> {};

// In either stuffing reading (spec/fba.md §2): segments and raw fields interleave, and segment
// ends are counted in consumed bits, whatever stuffing (real, or only apparent to a reader that
// counts on into the look-ahead) falls in the 14 bits given back.
TEST_P(FbaSegments, SegmentsAndRawFieldsInterleaveEvenWithStuffingInTheLookahead) {
  const std::uint64_t seed = test::test_seed(test::kFbaSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  int stuffed_in_lookahead = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int size = 1 + static_cast<int>(rng() % 1200);
    std::vector<std::vector<int>> symbols(3);
    std::vector<int> zeros(3);
    FbaBitWriter writer(GetParam());
    const int increment = 1 << (trial % 4);
    FrequencyModel enc_model(size, increment);
    for (int seg = 0; seg < 3; ++seg) {
      ArithmeticEncoder ac(writer);
      const int count = static_cast<int>(rng() % 6);
      for (int i = 0; i < count; ++i) {
        // Mostly the top symbols: the bottom of the interval, so long runs of 0 bits.
        const int s = rng() % 4 ? size - 1 - static_cast<int>(rng() % std::min(size, 3)) : static_cast<int>(rng() % size);
        symbols[static_cast<std::size_t>(seg)].push_back(s);
        ac.encode(s, enc_model);
      }
      ac.flush();
      zeros[static_cast<std::size_t>(seg)] = static_cast<int>(rng() % 24);
      writer.put(0, zeros[static_cast<std::size_t>(seg)]);
      writer.put_bit(1);
    }
    const std::uint64_t written = fba_bit_count(writer.position());
    writer.stuff_to_start_code();
    FbaBitReader reader(writer.bytes(), GetParam());
    FrequencyModel dec_model(size, increment);
    for (int seg = 0; seg < 3; ++seg) {
      ArithmeticDecoder ad(reader);
      for (const int s : symbols[static_cast<std::size_t>(seg)]) ASSERT_EQ(ad.decode(dec_model), s) << "trial " << trial;
      const std::uint64_t before = reader.position().raw_bits;
      ad.finish();
      if (before - reader.position().raw_bits != 14) ++stuffed_in_lookahead;  // a fixed 14 would be wrong here
      ASSERT_EQ(reader.get(zeros[static_cast<std::size_t>(seg)]), 0u);
      ASSERT_EQ(reader.get_bit(), 1) << "trial " << trial << " segment " << seg;
    }
    ASSERT_FALSE(reader.error());
    EXPECT_EQ(fba_bit_count(reader.position()), written);  // one bit count, both sides
    ASSERT_TRUE(dec_model == enc_model);
  }
  // Continuous reading: real stuffed bits fall in the look-ahead (the bits after a segment are
  // counted on); reference reading: the next segment's count starts afresh, so only a reader
  // counting on into the raw bits could see one there (FbaBits.MissingStuffedBitIsAnError).
  if (GetParam() == FbaStuffing::kContinuous) {
    EXPECT_GT(stuffed_in_lookahead, 0) << "the case the consumed-bit count exists for was never met";
  }
}

INSTANTIATE_TEST_SUITE_P(Readings, FbaSegments, testing::Values(FbaStuffing::kReference, FbaStuffing::kContinuous),
                         [](const auto& info) { return info.param == FbaStuffing::kReference ? "Reference" : "Continuous"; });

TEST(FbaArithmeticCoder, ModelsHalveAtTheTotalLimitAndStayUsable) {
  FrequencyModel one(2);  // the standard's +1: the total reaches 16383 exactly, then halves
  for (int i = 0; i < 16381; ++i) one.update(0);
  EXPECT_EQ(one.total(), 16383u);
  one.update(1);  // (16382 + 1) / 2 + (1 + 1) / 2 = 8192, then + 1
  EXPECT_EQ(one.total(), 8193u);
  EXPECT_EQ(one.cumulative(1), 2u);
  FrequencyModel eight(5, 8);
  for (int i = 0; i < 5000; ++i) {
    eight.update(i % 5);
    ASSERT_LE(eight.total(), FrequencyModel::kMaxTotal);
  }
  EXPECT_EQ(eight.increment(), 8);
  FrequencyModel m(3);
  for (int i = 0; i < 40000; ++i) m.update(i % 7 == 0 ? 2 : 0);
  EXPECT_LT(m.cumulative(0), FrequencyModel::kMaxTotal + 1);
  EXPECT_GT(m.cumulative(1) - m.cumulative(2), 0u);  // symbol 1, never seen, keeps a count
  EXPECT_EQ(m.cumulative(3), 0u);
  FbaBitWriter w;
  ArithmeticEncoder ac(w);
  FrequencyModel e = m, d = m;
  for (int i = 0; i < 100; ++i) ac.encode(i % 3, e);
  ac.flush();
  FbaBitReader r(w.bytes());
  ArithmeticDecoder ad(r);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(ad.decode(d), i % 3);
}

// The reciprocal division is exact where the coder uses it (numerators length * count below
// 2^30, divisors the totals 1..16383) and beyond: every divisor up to 2^16 at the numerators
// where a floor changes (k*d - 1, k*d), at both ends of the 32-bit range, and random pairs.
TEST(ExactReciprocal, DividesExactlyAtEveryFloorStep) {
  const std::uint64_t seed = test::test_seed(test::kFbaSeed);
  SCOPED_TRACE(test::reproduce_hint(seed));
  std::mt19937_64 rng(seed);
  for (std::uint32_t d = 1; d <= 65536; ++d) {
    const ExactReciprocal r(d);
    for (const std::uint32_t n : {0u, 1u, d - 1, d, d + 1, 2 * d - 1, 2 * d, (1u << 30) - 1, 1u << 30, 0xFFFFFFFFu})
      ASSERT_EQ(r.divide(n), n / d) << n << " / " << d;
    for (int i = 0; i < 8; ++i) {
      const std::uint64_t k = rng() % (0xFFFFFFFFull / d) + 1;  // k*d <= 2^32 - 1
      const auto n = static_cast<std::uint32_t>(k * d);
      ASSERT_EQ(r.divide(n), k) << n << " / " << d;
      ASSERT_EQ(r.divide(n - 1), k - 1) << n - 1 << " / " << d;
    }
  }
  for (int i = 0; i < 200000; ++i) {
    const auto d = static_cast<std::uint32_t>(rng() % ExactReciprocal::kMaxDivisor) + 1;
    const auto n = static_cast<std::uint32_t>(rng());
    ASSERT_EQ(ExactReciprocal(d).divide(n), n / d) << n << " / " << d;
  }
}

// The closed-form renormalisation against the rule it replaces (spec/fba.md §7, one shift at a
// time), for every interval low <= high whose ends lie on a grid and for random ones.
TEST(FbaArithmeticCoder, RenormalisationInOneStepMatchesTheShiftByShiftRule) {
  const auto one_at_a_time = [](std::uint32_t low, std::uint32_t high) {
    ArithmeticInterval r{low, high, 0};
    for (;;) {
      if (r.high < 32768) {
      } else if (r.low >= 32768) {
        r.low -= 32768;
        r.high -= 32768;
      } else if (r.low >= 16384 && r.high < 49152) {
        r.low -= 16384;
        r.high -= 16384;
      } else {
        return r;
      }
      r.low = 2 * r.low;
      r.high = 2 * r.high + 1;
      ++r.shifts;
    }
  };
  const auto check = [&](std::uint32_t low, std::uint32_t high) {
    ASSERT_EQ(arithmetic_renormalise(low, high), one_at_a_time(low, high)) << "low " << low << " high " << high;
  };
  for (std::uint32_t low = 0; low < 65536; low += 61)
    for (std::uint32_t high = low; high < 65536; high += 59) check(low, high);
  std::mt19937_64 rng(test::test_seed(test::kFbaSeed));
  for (int i = 0; i < 200000; ++i) {
    const auto a = static_cast<std::uint32_t>(rng() % 65536), b = static_cast<std::uint32_t>(rng() % 65536);
    const std::uint32_t width = static_cast<std::uint32_t>(rng() % 64);  // narrow intervals: long shift runs
    check(std::min(a, b), std::max(a, b));
    check(a, std::min(a + width, 65535u));
  }
}

TEST(FbaBits, ReaderGivesZerosPastTheEndAndTheErrorSticks) {
  const std::vector<std::uint8_t> one{0xA5};
  FbaBitReader r(one);
  EXPECT_EQ(r.get(8), 0xA5u);
  EXPECT_FALSE(r.error());
  EXPECT_EQ(r.get(8), 0u);
  EXPECT_EQ(r.error(), fba_errc::truncated);
  r.fail(fba_errc::marker_bit_missing);
  EXPECT_EQ(r.error(), fba_errc::truncated);  // the first error stays
}

TEST(FbaBits, MissingStuffedBitIsAnError) {
  const std::vector<std::uint8_t> zeros{0, 0, 0, 0x80};  // 24 zeros: the 23rd should be a 1
  FbaBitReader r(zeros, FbaStuffing::kContinuous);
  r.get(24);
  EXPECT_EQ(r.error(), fba_errc::stuffing_bit_missing);
  // The reference reading: outside a segment nothing is stuffed; inside, the error stands only
  // if the bit after the 22 zeros is one the encoder wrote (not given back at the segment end).
  FbaBitReader raw(zeros, FbaStuffing::kReference);
  EXPECT_EQ(raw.get(24), 0u);
  EXPECT_FALSE(raw.error());
  for (const int give_back : {0, 1}) {
    FbaBitReader seg(zeros, FbaStuffing::kReference);
    seg.begin_segment();
    seg.lookahead_bits(16);
    seg.lookahead_bits(7);  // payload bits 17..23: the 23rd is a 0 where a stuffed 1 belongs
    seg.end_segment(give_back);
    EXPECT_EQ(static_cast<bool>(seg.error()), give_back == 0) << "give back " << give_back;
    EXPECT_EQ(seg.position().raw_bits, 23u - static_cast<unsigned>(give_back));
  }
}

// The writer in both readings: reference stuffs only inside segments, from each segment's start,
// before the coded bit that would be the 23rd zero; continuous stuffs everywhere, at once.
TEST(FbaBits, WritersStuffWhereTheirReadingSays) {
  FbaBitWriter ref(FbaStuffing::kReference), cont(FbaStuffing::kContinuous);
  for (FbaBitWriter* w : {&ref, &cont}) {
    w->put(0, 10);  // a raw field of zeros
    w->begin_segment();
    w->put(0, 22);
    w->end_segment();  // 22 zeros end the segment: nothing follows them in it
    w->begin_segment();
    w->put(0, 23);
    w->end_segment();
  }
  EXPECT_EQ(ref.stuffed_bits(), (std::vector<std::uint64_t>{54}));  // before the 23rd zero of segment 2
  EXPECT_EQ(cont.stuffed_bits(), (std::vector<std::uint64_t>{22, 45}));  // counting the raw field's zeros
  EXPECT_EQ(ref.position().raw_bits, 10u + 22 + 23 + 1);
  EXPECT_EQ(cont.position().raw_bits, 10u + 22 + 23 + 2);
}

}  // namespace
}  // namespace fapcast
