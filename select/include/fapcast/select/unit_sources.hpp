#pragma once
// Where each unit of a search was cut from: the take of the voice's corpus and the phones that
// take recorded, beside the target phones the unit stands for. The search matches viseme
// classes, not phones, so a unit may record other phones of the same classes than those asked
// for (the weak "was" of MOCHA's fsew0_001, W AH Z, is served by the [AY Z] of "wisely"): this is
// where a reader sees it (spec/search.md, "Where the units come from").
#include "fapcast/phonetics/phone.hpp"
#include "fapcast/select/phone_graph.hpp"
#include "fapcast/select/unit_search.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace fapcast {

struct UnitSource {
  Unit unit;                       // target phones [first_target, first_target + length)
  std::uint32_t take = 0;          // the graph's utterance index: the corpus take, in corpus order
  std::size_t first_in_take = 0;   // the position of the unit's first phone within the take
  std::vector<Phone> take_phones;  // every phone the take recorded, in spoken order
};

// One UnitSource per unit of `result`, in order. `state_phones` gives the phone recorded in each
// state of `graph` (Voice::state_phones). Throws std::invalid_argument when `state_phones` is not
// one per state or a unit reaches past the graph or out of its take.
std::vector<UnitSource> unit_sources(const PhoneGraph& graph, std::span<const Phone> state_phones,
                                     const SearchResult& result);

// "SIL [W AA Z] SIL": the take's phones, the unit's in brackets.
std::string describe_take(const UnitSource& source);

}  // namespace fapcast
