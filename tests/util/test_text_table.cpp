// util/text_table: the summary table, compared with literal text written by hand.
#include "util/text_table.hpp"

#include <gtest/gtest.h>

#include <sstream>

using exactvis::print_table;

TEST(TextTable, ShowsTheFirstRowsAndCountsTheRest) {
  std::ostringstream out;
  std::vector<std::vector<std::string>> rows;
  for (int i = 0; i < 25; ++i) rows.push_back({std::to_string(i * 7), i % 2 ? "hidden" : "visible"});
  print_table(out, {"triangle", "state"}, rows, 1000, 3);
  EXPECT_EQ(out.str(),
            "  triangle  state\n"
            "  0         visible\n"
            "  7         hidden\n"
            "  14        visible\n"
            "  997 more, use --json\n");
}

TEST(TextTable, AllRowsShownMeansNoMoreLine) {
  std::ostringstream out;
  print_table(out, {"a", "bb"}, {{"xyz", "1"}, {"w", "22"}}, 2);
  EXPECT_EQ(out.str(), "  a    bb\n  xyz  1\n  w    22\n");
}

TEST(TextTable, EmptyResultPrintsNothing) {
  std::ostringstream out;
  print_table(out, {"a"}, {}, 0);
  EXPECT_EQ(out.str(), "");
}

TEST(TextTable, RowsBeyondWhatIsShownAreNotPrinted) {
  std::ostringstream out;
  print_table(out, {"a"}, {{"1"}, {"2"}}, 2, 1);
  EXPECT_EQ(out.str(), "  a\n  1\n  1 more, use --json\n");
}
