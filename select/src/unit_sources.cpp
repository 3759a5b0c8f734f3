#include "fapcast/select/unit_sources.hpp"

#include <stdexcept>

namespace fapcast {

std::vector<UnitSource> unit_sources(const PhoneGraph& graph, std::span<const Phone> state_phones,
                                     const SearchResult& result) {
  if (state_phones.size() != graph.size())
    throw std::invalid_argument("unit sources: " + std::to_string(state_phones.size()) + " state phones for " +
                                std::to_string(graph.size()) + " states");
  std::vector<UnitSource> sources;
  sources.reserve(result.units.size());
  for (const Unit& unit : result.units) {
    const StateId first = unit.first_state;
    if (unit.length == 0 || first >= graph.size() || unit.length > graph.size() - first)
      throw std::invalid_argument("unit sources: a unit reaches past the graph's " + std::to_string(graph.size()) +
                                  " states");
    const std::uint32_t take = graph.state(first).utterance;
    if (graph.state(first + unit.length - 1).utterance != take)
      throw std::invalid_argument("unit sources: a unit runs out of its take (" + std::to_string(take) + ")");
    // A take's states are contiguous (PhoneGraph's invariant): walk to its ends.
    StateId begin = first;
    while (graph.has_parent(begin)) --begin;
    StateId end = first + 1;
    while (graph.has_child(end - 1)) ++end;
    UnitSource s{unit, take, first - begin, {state_phones.begin() + begin, state_phones.begin() + end}};
    sources.push_back(std::move(s));
  }
  return sources;
}

std::string describe_take(const UnitSource& source) {
  std::string out;
  for (std::size_t i = 0; i < source.take_phones.size(); ++i) {
    if (i > 0) out += ' ';
    if (i == source.first_in_take) out += '[';
    out += arpabet(source.take_phones[i]);
    if (i + 1 == source.first_in_take + source.unit.length) out += ']';
  }
  return out;
}

}  // namespace fapcast
