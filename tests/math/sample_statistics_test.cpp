#include "fapcast/math/sample_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace fapcast {
namespace {

TEST(SampleStatistics, PercentilesInterpolateBetweenOrderStatistics) {
  const std::vector<double> x{4, 1, 3, 2, 5};  // sorted 1..5
  EXPECT_DOUBLE_EQ(percentile(x, 0), 1);
  EXPECT_DOUBLE_EQ(percentile(x, 50), 3);
  EXPECT_DOUBLE_EQ(percentile(x, 100), 5);
  EXPECT_DOUBLE_EQ(percentile(x, 95), 4.8);  // position 0.95 x 4 = 3.8
  EXPECT_DOUBLE_EQ(percentile(x, 5), 1.2);
  EXPECT_THROW(percentile(std::vector<double>{}, 50), std::invalid_argument);
  EXPECT_THROW(percentile(x, 101), std::invalid_argument);
}

TEST(SampleStatistics, PearsonIsScaleAndOffsetFreeAndSkipsMissingPairs) {
  const std::vector<double> a{1, 2, 3, 4, 5, 6};
  std::vector<double> b, c;
  for (double v : a) {
    b.push_back(-3 * v + 7);
    c.push_back(v * v);
  }
  EXPECT_NEAR(pearson_correlation(a, b), -1, 1e-12);
  EXPECT_GT(pearson_correlation(a, c), 0.95);
  EXPECT_LT(pearson_correlation(a, c), 1);
  std::vector<double> gappy = a;
  gappy[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NEAR(pearson_correlation(gappy, a), 1, 1e-12);
  EXPECT_EQ(pearson_correlation(a, std::vector<double>(6, 2.0)), 0.0);  // a constant curve
  EXPECT_THROW(pearson_correlation(a, std::vector<double>(5, 1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
