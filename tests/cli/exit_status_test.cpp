// The exit-status rule (cli/exit_status.hpp, spec/cli.md "Exit codes"): whose fault an exception
// is decides the code, the innermost of a nested chain decides, and the message says which.
#include "command.hpp"
#include "exit_status.hpp"

#include "fapcast/core/input_error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <new>
#include <stdexcept>
#include <system_error>

namespace fapcast::test {
namespace {

using cli::exit_status;
using cli::ExitStatus;

template <typename E>
ExitStatus status_of(const E& e) {
  return exit_status(std::make_exception_ptr(e));
}

// `inner` thrown, then wrapped by std::throw_with_nested in `outer`.
template <typename Outer, typename Inner>
ExitStatus status_of_nested(const Outer& outer, const Inner& inner) {
  try {
    try {
      throw inner;
    } catch (...) {
      std::throw_with_nested(outer);
    }
  } catch (...) {
    return exit_status(std::current_exception());
  }
  return {};
}

TEST(ExitStatus, BadInputIsOneAndNamesFileLineAndRule) {
  const ExitStatus s = status_of(InputError({"joy.fap", 12, {}}, "mask-token-count", "67 tokens"));
  EXPECT_EQ(s.code, 1);
  EXPECT_EQ(s.message, "fapcast: error: joy.fap:12: mask-token-count: 67 tokens");
}

TEST(ExitStatus, InputOutputAndSystemFailuresAreOne) {
  EXPECT_EQ(status_of(std::runtime_error("out.fap: cannot write: No space left on device")).code, 1);
  EXPECT_EQ(status_of(std::system_error(std::make_error_code(std::errc::address_in_use), "bind")).code, 1);
  EXPECT_EQ(status_of(std::filesystem::filesystem_error("cannot create", std::make_error_code(std::errc::permission_denied)))
                .code,
            1);
}

TEST(ExitStatus, UsageIsTwo) {
  const ExitStatus s = status_of(cli::UsageError("say: output 'x.txt' must end in .fap"));
  EXPECT_EQ(s.code, 2);
  EXPECT_EQ(s.message, "fapcast: usage: say: output 'x.txt' must end in .fap");
}

TEST(ExitStatus, ProgrammingErrorsAreSeventyAndSaySo) {
  for (const ExitStatus& s : {status_of(std::logic_error("viseme class without phones")),
                              status_of(std::invalid_argument("concatenate_units: 3 targets, 4 states")),
                              status_of(std::out_of_range("vector::at")), status_of(std::bad_alloc())}) {
    EXPECT_EQ(s.code, 70) << s.message;
    EXPECT_EQ(s.message.rfind("fapcast: internal error: ", 0), 0u) << s.message;
    EXPECT_NE(s.message.find(" (this is a bug)"), std::string::npos) << s.message;
  }
  EXPECT_EQ(status_of(std::logic_error("viseme class without phones")).message,
            "fapcast: internal error: viseme class without phones (this is a bug)");
  EXPECT_EQ(status_of(42).code, 70);  // not even a std::exception
  EXPECT_EQ(status_of(42).message, "fapcast: internal error: an exception of unknown type (this is a bug)");
}

TEST(ExitStatus, TheInnermostCauseDecides) {
  // A bug inside a wrapper that adds context is still a bug; bad input inside one is still input.
  const ExitStatus bug = status_of_nested(std::runtime_error("recording utt0003"), std::invalid_argument("k > rank"));
  EXPECT_EQ(bug.code, 70);
  EXPECT_EQ(bug.message, "fapcast: internal error: recording utt0003: k > rank (this is a bug)");
  const ExitStatus input =
      status_of_nested(std::runtime_error("system 'diviseme' on utt0001"), InputError({"x.TextGrid", 4, {}}, "r", "d"));
  EXPECT_EQ(input.code, 1);
  EXPECT_EQ(input.message, "fapcast: error: system 'diviseme' on utt0001: x.TextGrid:4: r: d");
}

}  // namespace
}  // namespace fapcast::test
