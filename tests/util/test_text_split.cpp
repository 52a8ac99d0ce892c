// split and trim (util/text_split.hpp): empty items kept, a trailing separator gives a last empty item,
// only spaces and tabs trimmed.
#include "util/text_split.hpp"

#include <gtest/gtest.h>

using exactvis::split;
using exactvis::trim;

TEST(TextSplit, ItemsIncludingEmptyOnes) {
  EXPECT_EQ(split("a,,b", ','), (std::vector<std::string>{"a", "", "b"}));
  EXPECT_EQ(split("a,", ','), (std::vector<std::string>{"a", ""}));
  EXPECT_EQ(split(",a", ','), (std::vector<std::string>{"", "a"}));
  EXPECT_TRUE(split("", ',').empty());
  EXPECT_EQ(split("x;y", ','), (std::vector<std::string>{"x;y"}));
  EXPECT_EQ(split("1/2", '/'), (std::vector<std::string>{"1", "2"}));
}

TEST(TextSplit, TrimSpacesAndTabsOnly) {
  EXPECT_EQ(trim(" \t a b\t "), "a b");
  EXPECT_EQ(trim("   "), "");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim("\na\n"), "\na\n");
}
