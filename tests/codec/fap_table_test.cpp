// The constexpr FAP table against its machine-readable copy spec/faps.tsv.
#include "fapcast/codec/fap_table.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fapcast {
namespace {

std::vector<std::vector<std::string>> read_tsv(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot open " << path;
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool header_seen = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, '\t')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::string fapu_name(Fapu u) { return u == Fapu::kNone ? "none" : std::string(to_string(u)); }

TEST(FapTable, MatchesSpecTsvRowByRow) {
  const auto rows = read_tsv(std::string(FAPCAST_SOURCE_DIR) + "/spec/faps.tsv");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kFapCount));
  for (const auto& cells : rows) {
    ASSERT_EQ(cells.size(), 10u);
    const int n = std::stoi(cells[0]);
    SCOPED_TRACE("FAP " + cells[0] + " " + cells[1]);
    const FapInfo& row = fap_info(n);
    EXPECT_EQ(row.number, n);
    EXPECT_EQ(row.name, cells[1]);
    EXPECT_EQ(fapu_name(row.unit), cells[2]);
    EXPECT_EQ(row.unidirectional, cells[3] == "1");
    EXPECT_EQ(row.direction, cells[4]);
    EXPECT_EQ(row.group, std::stoi(cells[5]));
    std::string fps = "-";
    if (row.feature_point) fps = row.feature_point->label();
    if (row.also_moves) fps += "," + row.also_moves->label();
    EXPECT_EQ(fps, cells[6]);
    EXPECT_EQ(row.qp, std::stoi(cells[7]));
    EXPECT_EQ(row.range_i, std::stoi(cells[8]));
    EXPECT_EQ(row.range_p, std::stoi(cells[9]));
  }
}

TEST(FapTable, GroupsPartitionTheFapsInOrder) {
  int next = 1;
  for (int g = 1; g <= kGroupCount; ++g) {
    const FapRange r = fap_group(g);
    EXPECT_EQ(r.first, next) << "group " << g;
    for (int n = r.first; n <= r.last; ++n) EXPECT_EQ(fap_info(n).group, g) << "FAP " << n;
    next = r.last + 1;
  }
  EXPECT_EQ(next, kFapCount + 1);
}

TEST(FapTable, NamesAreUniqueAndLookUpBothWays) {
  for (const auto& row : fap_table()) {
    auto n = fap_number(row.name);
    ASSERT_TRUE(n.has_value()) << row.name;
    EXPECT_EQ(*n, row.number);
  }
  EXPECT_FALSE(fap_number("open_mouth").has_value());
}

TEST(FapTable, LowLevelFapsHaveUnitsAndSteps) {
  for (int n = kFirstLowLevelFap; n <= kFapCount; ++n) {
    EXPECT_NE(fap_info(n).unit, Fapu::kNone) << n;
    EXPECT_GT(fap_info(n).qp, 0) << n;
    EXPECT_GE(fap_info(n).range_i, fap_info(n).range_p) << n;
  }
}

}  // namespace
}  // namespace fapcast
