#pragma once
// What `fapcast` exits with when a command throws (spec/cli.md, "Exit codes"): the exception's
// root cause - the innermost of a std::throw_with_nested chain - decides.
//   1  bad input: fapcast::InputError, or any other std::runtime_error (a file that cannot be
//      opened or written, a socket that cannot be bound, a stream that breaks its format)
//   2  bad usage: UsageError (CLI11's own parse errors are handled before this)
//   70 internal error (EX_SOFTWARE): everything else - std::logic_error and its kin
//      (invalid_argument, out_of_range, length_error), std::bad_alloc, a non-std exception. A
//      library reports the user's bad input as InputError, so these are fapcast's bugs.
#include <exception>
#include <string>

namespace fapcast::cli {

// Exit codes of the command line.
enum ExitCode : int { kOk = 0, kBadInput = 1, kBadUsage = 2, kInternalError = 70 };

struct ExitStatus {
  ExitCode code = kOk;
  std::string message;  // one line for standard error, without the newline
};

// The exit code and message for `error` (non-null): "fapcast: error: a: b: c" (the nested
// messages, outermost first), "fapcast: usage: ...", or "fapcast: internal error: a: b (this is
// a bug)".
ExitStatus exit_status(const std::exception_ptr& error);

}  // namespace fapcast::cli
