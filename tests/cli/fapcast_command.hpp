#pragma once
// The `fapcast` executable under test (FAPCAST_EXE, defined for tests/cli only), quoted for the
// shell, followed by `args`.
#include <string>

namespace fapcast::test {

inline std::string fapcast(const std::string& args) { return std::string("'") + FAPCAST_EXE + "' " + args; }

}  // namespace fapcast::test
