// Double description of open cones in Plücker space, checked against the constraints themselves:
// every generator satisfies all constraints, every constraint is tight on enough rays, rays are extreme
// (their tight constraints have rank dim-1), and random points satisfying all constraints strictly are
// found inside the generated cone by an independent exact LP-free test (Carathéodory via rational elimination).
#include "region/polyhedral_cone6.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <set>

using namespace exactvis::region;

namespace {

IntVec6 random_vec(std::mt19937_64& rng, int range) {
  IntVec6 v;
  for (auto& c : v) c = static_cast<long>(rng() % (2 * range + 1)) - range;
  return v;
}

// The cone's vectors as GMP integers (ConeVector6::to_gmp: the stored integers, whatever their layer).
std::vector<IntVec6> gmp_all(const std::vector<ConeVector6>& vs) {
  std::vector<IntVec6> out;
  for (const auto& v : vs) out.push_back(v.to_gmp());
  return out;
}

int rank_of(std::vector<IntVec6> rows) {
  int rank = 0;
  std::vector<std::array<mpq_class, 6>> m;
  for (auto& r : rows) {
    std::array<mpq_class, 6> q;
    for (int k = 0; k < 6; ++k) q[k] = r[k];
    m.push_back(q);
  }
  for (int col = 0; col < 6 && rank < static_cast<int>(m.size()); ++col) {
    int p = rank;
    while (p < static_cast<int>(m.size()) && sgn(m[p][col]) == 0) ++p;
    if (p == static_cast<int>(m.size())) continue;
    std::swap(m[p], m[rank]);
    for (std::size_t r = 0; r < m.size(); ++r)
      if (static_cast<int>(r) != rank && sgn(m[r][col]) != 0) {
        mpq_class f = m[r][col] / m[rank][col];
        for (int k = 0; k < 6; ++k) m[r][k] -= f * m[rank][k];
      }
    ++rank;
  }
  return rank;
}

}  // namespace

TEST(PolyhedralCone6, GeneratorsSatisfyConstraintsAndRaysAreExtreme) {
  std::mt19937_64 rng(12345);
  int nonempty = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::optional<PolyhedralCone6> cone = whole_space_cone();
    std::vector<IntVec6> all;
    const int n = 4 + static_cast<int>(rng() % 9);
    for (int i = 0; i < n && cone; ++i) {
      IntVec6 w = random_vec(rng, 3);
      if (is_zero(w)) continue;
      all.push_back(w);
      cone = intersect_open_halfspace(*cone, w);
    }
    if (!cone) continue;
    ++nonempty;
    // Every generator lies in the closure of every constraint ever added (also the dropped redundant ones).
    for (const auto& w : all) {
      for (const auto& r : gmp_all(cone->rays)) EXPECT_GE(sgn(dot(w, r)), 0);
      for (const auto& b : gmp_all(cone->lineality)) EXPECT_EQ(sgn(dot(w, b)), 0);
    }
    // Full dimension.
    std::vector<IntVec6> gens = gmp_all(cone->rays);
    for (const auto& b : gmp_all(cone->lineality)) gens.push_back(b);
    EXPECT_EQ(rank_of(gens), 6);
    // Extremality: the constraints tight at a ray, with the lineality, have rank 5 - dim(lineality) ... i.e.
    // the ray spans, modulo lineality, a 1-dimensional face.
    const int dim = 6 - static_cast<int>(cone->lineality.size());
    for (const auto& r : gmp_all(cone->rays)) {
      std::vector<IntVec6> tight;
      for (const auto& w : all)
        if (sgn(dot(w, r)) == 0) tight.push_back(w);
      EXPECT_EQ(rank_of(tight), dim - 1);
    }
    // Incidence bits agree with the kept constraints.
    for (std::size_t r = 0; r < cone->rays.size(); ++r)
      for (std::size_t i = 0; i < cone->constraints.size(); ++i)
        EXPECT_EQ(cone->incidence[r][i], sgn(dot(cone->constraints[i].to_gmp(), cone->rays[r].to_gmp())) == 0);
    // The interior point is strictly inside every constraint.
    const IntVec6 c = interior_point(*cone);
    for (const auto& w : all) EXPECT_GT(sgn(dot(w, c)), 0);
  }
  EXPECT_GT(nonempty, 50);
}

TEST(PolyhedralCone6, RandomFeasiblePointsAreNotCutOff) {
  // Points drawn first, constraints chosen to keep them strictly inside: the cone must stay non-empty
  // and keep them in its closure (they are positive combinations of generators iff no kept constraint
  // excludes them, which we check on the kept constraint list).
  std::mt19937_64 rng(777);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<IntVec6> pts;
    for (int i = 0; i < 3; ++i) pts.push_back(random_vec(rng, 5));
    std::optional<PolyhedralCone6> cone = whole_space_cone();
    for (int i = 0; i < 10; ++i) {
      IntVec6 w = random_vec(rng, 4);
      bool ok = !is_zero(w);
      for (const auto& p : pts) ok = ok && sgn(dot(w, p)) > 0;
      if (!ok) continue;
      cone = intersect_open_halfspace(*cone, w);
      ASSERT_TRUE(cone.has_value());
    }
    for (const auto& p : pts) EXPECT_TRUE(in_open_cone(*cone, p));
  }
}

namespace {

// Brute force: the extreme rays of the pointed cone {x : w_i . x >= 0} are the feasible directions spanned
// by the 1-dimensional null spaces of 5-subsets of the constraints (normalised, deduplicated).
std::set<std::vector<long>> brute_force_rays(const std::vector<IntVec6>& cons) {
  std::set<std::vector<long>> out;
  const std::size_t n = cons.size();
  std::vector<std::size_t> idx(5);
  std::function<void(std::size_t, std::size_t)> rec = [&](std::size_t start, std::size_t depth) {
    if (depth == 5) {
      std::vector<IntVec6> rows;
      for (auto i : idx) rows.push_back(cons[i]);
      if (rank_of(rows) != 5) return;
      // Null vector by cofactors (generalised cross product of the 5 rows).
      IntVec6 x;
      for (int col = 0; col < 6; ++col) {
        std::vector<IntVec6> minor;
        std::array<std::array<mpq_class, 5>, 5> m;
        for (int r = 0; r < 5; ++r) {
          int cc = 0;
          for (int k = 0; k < 6; ++k)
            if (k != col) m[r][cc++] = rows[r][k];
        }
        // determinant by elimination
        mpq_class det = 1;
        for (int c = 0; c < 5; ++c) {
          int p = c;
          while (p < 5 && sgn(m[p][c]) == 0) ++p;
          if (p == 5) {
            det = 0;
            break;
          }
          if (p != c) {
            std::swap(m[p], m[c]);
            det = -det;
          }
          det *= m[c][c];
          for (int r = c + 1; r < 5; ++r) {
            mpq_class f = m[r][c] / m[c][c];
            for (int k = c; k < 5; ++k) m[r][k] -= f * m[c][k];
          }
        }
        mpz_class d = det.get_num();
        x[col] = (col % 2 == 0) ? d : mpz_class(-d);
      }
      for (int s : {1, -1}) {
        IntVec6 y = x;
        if (s < 0)
          for (auto& c : y) c = -c;
        bool ok = true;
        for (const auto& w : cons) ok = ok && sgn(dot(w, y)) >= 0;
        if (!ok) continue;
        normalize(y);
        std::vector<long> key;
        for (const auto& c : y) key.push_back(c.get_si());
        out.insert(key);
      }
      return;
    }
    for (std::size_t i = start; i < n; ++i) {
      idx[depth] = i;
      rec(i + 1, depth + 1);
    }
  };
  rec(0, 0);
  return out;
}

}  // namespace

TEST(PolyhedralCone6, RaysMatchBruteForceEnumeration) {
  std::mt19937_64 rng(31337);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::optional<PolyhedralCone6> cone = whole_space_cone();
    std::vector<IntVec6> all;
    const int n = 7 + static_cast<int>(rng() % 5);
    for (int i = 0; i < n && cone; ++i) {
      IntVec6 w = random_vec(rng, 2);  // small range: many degenerate (non-simple) configurations
      if (is_zero(w)) continue;
      all.push_back(w);
      cone = intersect_open_halfspace(*cone, w);
    }
    if (!cone || !cone->lineality.empty()) continue;
    std::set<std::vector<long>> dd;
    for (auto r : gmp_all(cone->rays)) {
      normalize(r);
      std::vector<long> key;
      for (const auto& c : r) key.push_back(c.get_si());
      dd.insert(key);
    }
    EXPECT_EQ(dd.size(), cone->rays.size()) << "duplicate rays, trial " << trial;
    EXPECT_EQ(dd, brute_force_rays(all)) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 50);
}

namespace {

void expect_same_cone(const PolyhedralCone6& a, const PolyhedralCone6& b) {
  ASSERT_EQ(a.constraints.size(), b.constraints.size());
  for (std::size_t i = 0; i < a.constraints.size(); ++i) EXPECT_TRUE(a.constraints[i] == b.constraints[i]);
  ASSERT_EQ(a.rays.size(), b.rays.size());
  for (std::size_t i = 0; i < a.rays.size(); ++i) EXPECT_TRUE(a.rays[i] == b.rays[i]) << "ray " << i;
  ASSERT_EQ(a.incidence.size(), b.incidence.size());
  for (std::size_t i = 0; i < a.incidence.size(); ++i) EXPECT_TRUE(a.incidence[i] == b.incidence[i]);
  ASSERT_EQ(a.lineality.size(), b.lineality.size());
  for (std::size_t i = 0; i < a.lineality.size(); ++i) EXPECT_TRUE(a.lineality[i] == b.lineality[i]);
}

}  // namespace

// split_crossing gives exactly the two cones of intersect_open_halfspace with w and with -w (same rays in the
// same order: the PVS's witnesses depend on the order), and hyperplane_signs the relation of
// relation_to_halfspace, on random cones and random cutting hyperplanes.
TEST(PolyhedralCone6, SplitCrossingEqualsBothHalfspaceIntersections) {
  std::mt19937_64 rng(4242);
  int crossings = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::optional<PolyhedralCone6> cone = whole_space_cone();
    const int n = 3 + static_cast<int>(rng() % 10);
    for (int i = 0; i < n && cone; ++i) {
      const IntVec6 w = random_vec(rng, 4);
      if (!is_zero(w)) cone = intersect_open_halfspace(*cone, w);
    }
    if (!cone) continue;
    for (int cut = 0; cut < 4; ++cut) {
      const IntVec6 wg = random_vec(rng, 5);
      if (is_zero(wg)) continue;
      const ConeVector6 w(wg);
      const HyperplaneSigns signs = hyperplane_signs(*cone, w);
      EXPECT_EQ(signs.relation, relation_to_halfspace(*cone, w));
      if (signs.relation != HalfspaceRelation::Crossing || signs.by_lineality) continue;
      ++crossings;
      const auto parts = split_crossing(*cone, w, signs);
      const auto plus = intersect_open_halfspace(*cone, w), minus = intersect_open_halfspace(*cone, w.negated());
      ASSERT_TRUE(plus && minus);
      expect_same_cone(parts[0], *plus);
      expect_same_cone(parts[1], *minus);
    }
  }
  EXPECT_GT(crossings, 200);
}
