// util/format_number: the printed forms, checked against literal strings written by hand.
#include "util/format_number.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using exactvis::format_count;
using exactvis::format_fraction;
using exactvis::format_measure;

TEST(FormatNumber, Counts) {
  EXPECT_EQ(format_count(0), "0");
  EXPECT_EQ(format_count(254633), "254633");
  EXPECT_EQ(format_count(-7), "-7");
  EXPECT_EQ(format_count(std::numeric_limits<std::int64_t>::min()), "-9223372036854775808");
}

TEST(FormatNumber, MeasuresHaveFourSignificantDigitsAndNoTrailingZeros) {
  EXPECT_EQ(format_measure(0.0), "0");
  EXPECT_EQ(format_measure(-0.0), "0");
  EXPECT_EQ(format_measure(1.5), "1.5");
  EXPECT_EQ(format_measure(12.3456), "12.35");
  EXPECT_EQ(format_measure(0.0123449), "0.01234");
  EXPECT_EQ(format_measure(1234567.0), "1.235e+06");
  EXPECT_EQ(format_measure(2.0), "2");
  EXPECT_EQ(format_measure(std::nan("")), "nan");
  EXPECT_EQ(format_measure(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(FormatNumber, Fractions) {
  EXPECT_EQ(format_fraction(12, 40), "12 of 40 (30%)");
  EXPECT_EQ(format_fraction(1, 3), "1 of 3 (33.33%)");
  EXPECT_EQ(format_fraction(0, 0), "0 of 0");
}
