// region/exterior_witness: each condition of an exterior witness rejected on a hand-built model, valid ones
// accepted, and random candidates agree with the independent oracle (tests/oracles/exterior_oracle).
#include "region/exterior_witness.hpp"

#include "region/convex_polygon_3.hpp"

#include "oracles/exterior_oracle.hpp"
#include "tests/region/exterior_test_scenes.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;
using exterior_test::ModelBuilder;

namespace {

Vec3<Exact> v(double x, double y, double z) { return {Exact(x), Exact(y), Exact(z)}; }

TEST(ExteriorWitness, EachConditionIsChecked) {
  // A unit box, a triangle T at z = 2 above it and a triangle O through T's interior point (0.5, 0.3, 2)
  // standing vertically (non-coplanar), a coplanar triangle overlapping T.
  ModelBuilder b;
  b.box({0, 0, 0}, {1, 1, 1});
  const std::int64_t t = b.triangle({0, 0, 2}, {1, 0, 2}, {0, 1, 2});
  b.triangle({0.5, 0.3, 2}, {0.7, 0.3, 2.5}, {0.6, 0.3, 3});
  b.triangle({0.1, 0.1, 2}, {0.5, 0.1, 2}, {0.1, 0.5, 2});
  const Scene& s = b.scene;
  const TriangleIndex index(s);
  const Box3 box = bounding_box(s);
  auto check = [&](double qx, double qy, double qz, const Vec3<Exact>& d) {
    return check_exterior_witness(s, index, box, t, {to_rational(Point3{qx, qy, qz}), d});
  };
  EXPECT_EQ(check(0.2, 0.6, 2, v(0, 0, 1)), ExteriorWitnessCheck::Valid);
  EXPECT_EQ(check(0.2, 0.6, 2, v(0, 0, -1)), ExteriorWitnessCheck::Blocked);      // the box below
  EXPECT_EQ(check(0.2, 0.6, 2, v(1, 0, 0)), ExteriorWitnessCheck::ParallelToTriangle);
  EXPECT_EQ(check(0.5, 0.5, 2, v(0, 0, 1)), ExteriorWitnessCheck::NotInRelativeInterior);  // on T's edge
  EXPECT_EQ(check(0.5, 0.3, 2, v(0, -1, 1)), ExteriorWitnessCheck::OnOtherTriangle);     // q on O
  EXPECT_EQ(check(0.2, 0.2, 2, v(0, 0, 1)), ExteriorWitnessCheck::Valid);  // q on the coplanar triangle
  EXPECT_EQ(check(0.4, 0.25, 2, v(0.2, 0.05, 0.6)), ExteriorWitnessCheck::Blocked);  // through O
}

TEST(ExteriorWitness, RoundingKeepsAValidWitness) {
  ModelBuilder b;
  b.box({0, 0, 0}, {1, 1, 1});
  const Scene& s = b.scene;
  const TriangleIndex index(s);
  const Box3 box = bounding_box(s);
  const auto tri = triangle_points(s, 0);
  const ExteriorWitness w{centroid(Polygon3{tri[0], tri[1], tri[2]}), v(0, 0, -3)};
  ASSERT_EQ(check_exterior_witness(s, index, box, 0, w), ExteriorWitnessCheck::Valid);
  const ExteriorWitness r = round_exterior_witness(s, index, box, 0, w);
  EXPECT_EQ(check_exterior_witness(s, index, box, 0, r), ExteriorWitnessCheck::Valid);
  double x;
  EXPECT_TRUE(exact_double(r.q.x, &x) && exact_double(r.q.y, &x) && exact_double(r.q.z, &x));
}

TEST(ExteriorWitness, RandomCandidatesAgreeWithOracle) {
  // Box in an open box with a few loose triangles: random q in each triangle, random integer directions.
  ModelBuilder b;
  b.box({-1, -1, -1}, {2, 2, 2}, false);
  b.box({0, 0, 0}, {1, 1, 1});
  b.triangle({0, 0, 1.5}, {1, 0, 1.5}, {0.5, 1, 1.5});
  b.triangle({-0.5, 0.5, 0.5}, {-0.5, 0.7, 1.9}, {-0.5, -0.5, 1.9});
  const Scene& s = b.scene;
  const TriangleIndex index(s);
  const Box3 box = bounding_box(s);
  const auto os = region_test::oracle_scene(s);
  std::mt19937_64 rng(5);
  int valid = 0, blocked = 0;
  for (int k = 0; k < 400; ++k) {
    const std::int64_t t = static_cast<std::int64_t>(rng() % s.triangles.size());
    const auto tri = triangle_points(s, t);
    const RationalPoint3 q = random_interior_point(Polygon3{tri[0], tri[1], tri[2]}, rng);
    const Vec3<Exact> d = v(static_cast<int>(rng() % 7) - 3, static_cast<int>(rng() % 7) - 3, static_cast<int>(rng() % 7) - 3);
    if (CGAL::sign(d.x) == 0 && CGAL::sign(d.y) == 0 && CGAL::sign(d.z) == 0) continue;
    const ExteriorWitnessCheck c = check_exterior_witness(s, index, box, t, {q, d});
    std::string why;
    const bool oracle_valid = oracle::exterior_witness_is_valid(os, static_cast<std::size_t>(t), region_test::qv(q),
                                                                region_test::qv(d), &why);
    if (c == ExteriorWitnessCheck::Valid) {
      EXPECT_TRUE(oracle_valid) << why;
      ++valid;
    }
    if (c == ExteriorWitnessCheck::Blocked || c == ExteriorWitnessCheck::ParallelToTriangle) {
      EXPECT_FALSE(oracle_valid);
      ++blocked;
    }
  }
  EXPECT_GT(valid, 40);
  EXPECT_GT(blocked, 40);
}

}  // namespace
