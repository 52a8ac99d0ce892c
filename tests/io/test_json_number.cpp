// Exact numbers in JSON: doubles stay numbers (bit-exact through text), other rationals become "num/den",
// and reading back gives the same exact value.
#include "io/json_number.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

using namespace exactvis;

TEST(JsonNumber, DoublesAreNumbersOthersAreStrings) {
  EXPECT_TRUE(exact_to_json(Exact(0.1)).is_number());
  EXPECT_EQ(exact_to_json(Exact(0.1)).get<double>(), 0.1);
  EXPECT_TRUE(exact_to_json(Exact(1) / Exact(3)).is_string());
  EXPECT_EQ(exact_to_json(Exact(1) / Exact(3)).get<std::string>(), "1/3");
  EXPECT_EQ(exact_to_json(Exact(-2) / Exact(6)).get<std::string>(), "-1/3");
  // 2^60 + 1 is an integer but not a double.
  const Exact big = Exact(1152921504606846976.0) + Exact(1);
  EXPECT_TRUE(exact_to_json(big).is_string());
  EXPECT_EQ(exact_to_json(big).get<std::string>(), "1152921504606846977");
}

TEST(JsonNumber, RoundTripThroughText) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 2000; ++i) {
    double d;
    const std::uint64_t bits = rng();
    std::memcpy(&d, &bits, 8);
    if (!std::isfinite(d)) continue;
    const Exact x = (i % 2 == 0) ? Exact(d) : Exact(d) / Exact(static_cast<double>(rng() % 1000 + 3));
    const std::string text = nlohmann::json{{"v", exact_to_json(x)}}.dump();
    const Exact back = exact_from_json(nlohmann::json::parse(text)["v"]);
    ASSERT_EQ(back, x) << text;
  }
  // Integers beyond 2^53 are exact as JSON integers (not through a double).
  EXPECT_EQ(exact_from_json(nlohmann::json::parse("9223372036854775807")), Exact(std::string("9223372036854775807")));
  EXPECT_EQ(exact_from_json(nlohmann::json::parse("18446744073709551615")), Exact(std::string("18446744073709551615")));
  EXPECT_EQ(exact_from_json(nlohmann::json("7/14")), Exact(1) / Exact(2));
  EXPECT_THROW(exact_from_json(nlohmann::json(true)), std::invalid_argument);
  EXPECT_THROW(exact_from_json(nlohmann::json("1/0")), std::invalid_argument);
  EXPECT_THROW(exact_from_json(nlohmann::json("abc")), std::invalid_argument);
}
