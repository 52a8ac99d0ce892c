// IncidenceSet (region/incidence_set.hpp) against an independent model, a std::vector<bool>, under random
// sequences of the operations the double description uses, on sizes below, at and beyond the inline
// capacity (so both the in-object and the heap storage are exercised, and growth across the boundary).
#include "region/incidence_set.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using exactvis::region::IncidenceSet;

namespace {

void expect_same(const IncidenceSet& s, const std::vector<bool>& m) {
  ASSERT_EQ(s.size(), m.size());
  std::size_t c = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    ASSERT_EQ(s.test(i), m[i]) << "bit " << i << " of " << m.size();
    ASSERT_EQ(s[i], m[i]);
    c += m[i] ? 1 : 0;
  }
  ASSERT_EQ(s.count(), c);
}

}  // namespace

TEST(IncidenceSet, MatchesAVectorOfBoolUnderRandomOperations) {
  std::mt19937_64 rng(11);
  for (int round = 0; round < 400; ++round) {
    const std::size_t n = rng() % 300;
    IncidenceSet a(n), b(n);
    std::vector<bool> ma(n, false), mb(n, false);
    expect_same(a, ma);
    for (int op = 0; op < 60 && n > 0; ++op) {
      const std::size_t i = rng() % n;
      const bool v = rng() % 3 != 0;
      if (rng() % 2) a.set(i, v), ma[i] = v;
      else b.set(i, v), mb[i] = v;
    }
    expect_same(a, ma);
    expect_same(b, mb);
    // Subset, both ways, against the model.
    bool sub = true, sub_back = true;
    for (std::size_t i = 0; i < n; ++i) {
      sub = sub && (!ma[i] || mb[i]);
      sub_back = sub_back && (!mb[i] || ma[i]);
    }
    EXPECT_EQ(a.is_subset_of(b), sub);
    EXPECT_EQ(b.is_subset_of(a), sub_back);
    EXPECT_EQ(a == b, ma == mb);
    // Intersection.
    IncidenceSet c = a;
    c &= b;
    std::vector<bool> mc(n);
    for (std::size_t i = 0; i < n; ++i) mc[i] = ma[i] && mb[i];
    expect_same(c, mc);
    EXPECT_TRUE(c.is_subset_of(a));
    EXPECT_TRUE(c.is_subset_of(b));
    // Widening by one bit (the double description step), possibly across the inline capacity.
    const std::size_t grow = n + 1 + rng() % 70;
    IncidenceSet w = a;
    w.resize(grow);
    std::vector<bool> mw = ma;
    mw.resize(grow, false);
    expect_same(w, mw);
    w.set(grow - 1, true);
    mw[grow - 1] = true;
    expect_same(w, mw);
    // Shrinking drops the high bits (count sees only the kept ones).
    const std::size_t keep = n == 0 ? 0 : rng() % n;
    w.resize(keep);
    mw.resize(keep);
    expect_same(w, mw);
    // All set, then one cleared.
    IncidenceSet f(grow);
    f.set_all();
    std::vector<bool> mf(grow, true);
    expect_same(f, mf);
    f.set(0, false);
    mf[0] = false;
    expect_same(f, mf);
  }
}

TEST(IncidenceSet, CopiesAreIndependent) {
  for (const std::size_t n : {5u, 128u, 129u, 500u}) {
    IncidenceSet a(n);
    a.set(n - 1);
    IncidenceSet b = a;
    b.set(0);
    EXPECT_FALSE(a.test(0));
    EXPECT_TRUE(b.test(0));
    EXPECT_TRUE(a.test(n - 1) && b.test(n - 1));
    EXPECT_EQ(a.count(), 1u);
    EXPECT_EQ(b.count(), n == 1 ? 1u : 2u);
  }
}
