// Where the search's units were cut from: the take and its phones, beside the phones asked for.
#include "fapcast/select/unit_sources.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fapcast {
namespace {

// A "was" recorded with a full open vowel, and an "us".
const std::vector<Phone> kWas{Phone::SIL, Phone::W, Phone::AA, Phone::Z, Phone::SIL};
const std::vector<Phone> kUs{Phone::SIL, Phone::AH, Phone::S, Phone::SIL};

// Takes as phone lists, each phone one frame; states in take order.
struct Takes {
  PhoneGraph graph;
  std::vector<Phone> phones;
};

Takes takes(const std::vector<std::vector<Phone>>& list) {
  std::vector<PhoneState> states;
  std::vector<Phone> phones;
  std::uint32_t frame = 0;
  for (std::uint32_t u = 0; u < list.size(); ++u)
    for (Phone p : list[u]) {
      states.push_back({u, search_viseme(p), {frame++, 1}});
      phones.push_back(p);
    }
  return {PhoneGraph(std::move(states)), std::move(phones)};
}

TEST(UnitSources, NameTheTakeAndThePhonesItRecorded) {
  // Take 0 is a citation "was" (W AA Z), take 1 "us"; a weak "was us" (W AH Z AH S) is spelt by
  // classes, so the search may take "was" whole for W AH Z and "us" for AH S.
  const Takes t = takes({kWas, kUs});
  SearchResult result;
  result.units = {{1, 0, 3}, {6, 3, 2}};
  const std::vector<UnitSource> sources = unit_sources(t.graph, t.phones, result);
  ASSERT_EQ(sources.size(), 2u);
  EXPECT_EQ(sources[0].take, 0u);
  EXPECT_EQ(sources[0].first_in_take, 1u);
  EXPECT_EQ(sources[0].take_phones, kWas);
  EXPECT_EQ(sources[0].unit, (Unit{1, 0, 3}));
  EXPECT_EQ(describe_take(sources[0]), "SIL [W AA Z] SIL");
  EXPECT_EQ(sources[1].take, 1u);
  EXPECT_EQ(sources[1].first_in_take, 1u);
  EXPECT_EQ(describe_take(sources[1]), "SIL [AH S] SIL");
}

TEST(UnitSources, AUnitAtATakesEdgesBracketsThoseEdges) {
  const Takes t = takes({{Phone::SIL, Phone::P, Phone::AA, Phone::SIL}});
  SearchResult result;
  result.units = {{0, 0, 4}};
  EXPECT_EQ(describe_take(unit_sources(t.graph, t.phones, result).at(0)), "[SIL P AA SIL]");
  result.units = {{3, 0, 1}};
  EXPECT_EQ(describe_take(unit_sources(t.graph, t.phones, result).at(0)), "SIL P AA [SIL]");
}

TEST(UnitSources, RefusesUnitsThatAreNotTheGraphs) {
  const Takes t = takes({kWas, kUs});
  SearchResult result;
  result.units = {{1, 0, 3}};
  EXPECT_THROW(unit_sources(t.graph, std::span<const Phone>(t.phones).first(3), result), std::invalid_argument);
  result.units = {{7, 0, 3}};  // past the last state
  EXPECT_THROW(unit_sources(t.graph, t.phones, result), std::invalid_argument);
  result.units = {{3, 0, 3}};  // from take 0 into take 1
  EXPECT_THROW(unit_sources(t.graph, t.phones, result), std::invalid_argument);
  result.units = {{1, 0, 0}};  // empty
  EXPECT_THROW(unit_sources(t.graph, t.phones, result), std::invalid_argument);
}

}  // namespace
}  // namespace fapcast
