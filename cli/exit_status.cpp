#include "exit_status.hpp"

#include "command.hpp"

#include <sstream>
#include <stdexcept>

namespace fapcast::cli {
namespace {

enum class Cause { kInput, kUsage, kInternal };

// What an exception says about whose fault it is.
Cause cause_of(const std::exception& e) {
  if (dynamic_cast<const UsageError*>(&e) != nullptr) return Cause::kUsage;
  if (dynamic_cast<const std::runtime_error*>(&e) != nullptr) return Cause::kInput;
  return Cause::kInternal;
}

// Writes the messages of `e` and the exceptions nested in it, outermost first, joined by ": ";
// returns the cause of the innermost.
Cause describe(std::ostream& out, const std::exception& e, bool first = true) {
  out << (first ? "" : ": ") << e.what();
  try {
    std::rethrow_if_nested(e);
  } catch (const std::exception& inner) {
    return describe(out, inner, false);
  } catch (...) {
    out << ": an exception of unknown type";
    return Cause::kInternal;
  }
  return cause_of(e);
}

}  // namespace

ExitStatus exit_status(const std::exception_ptr& error) {
  std::ostringstream text;
  Cause cause = Cause::kInternal;
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    cause = describe(text, e);
  } catch (...) {
    text << "an exception of unknown type";
  }
  switch (cause) {
    case Cause::kUsage:
      return {kBadUsage, "fapcast: usage: " + text.str()};
    case Cause::kInput:
      return {kBadInput, "fapcast: error: " + text.str()};
    case Cause::kInternal:
      break;
  }
  return {kInternalError, "fapcast: internal error: " + text.str() + " (this is a bug)"};
}

}  // namespace fapcast::cli
