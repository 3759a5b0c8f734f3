#pragma once
// The label every output derived from the reference talker carries (spec/talker.md): the talker
// is a known generator, not a person.
#include <string_view>

namespace fapcast {

inline constexpr std::string_view kSyntheticLabel =
    "SYNTHETIC: recorded by the fapcast reference talker, not captured from a person";

}  // namespace fapcast
