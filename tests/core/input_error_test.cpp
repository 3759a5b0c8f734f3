#include "fapcast/core/input_error.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

TEST(SynthInputError, FormatsLineForTextFormats) {
  const InputError e({"a.TextGrid", 12, std::nullopt}, "interval-order", "starts before 1.5");
  EXPECT_STREQ(e.what(), "a.TextGrid:12: interval-order: starts before 1.5");
  EXPECT_EQ(e.rule(), "interval-order");
  EXPECT_EQ(e.where().line, 12u);
}

TEST(SynthInputError, FormatsByteOffsetForBinaryFormats) {
  const InputError e({"", std::nullopt, 512}, "c3d-truncated", "x");
  EXPECT_STREQ(e.what(), "<memory>: byte 512: c3d-truncated: x");
}

}  // namespace
}  // namespace fapcast
