// Recognising closed convex models: accepted shapes (any winding), and each failing condition.
#include "aspect/convex_model.hpp"

#include "tests/aspect/aspect_test_models.hpp"

#include <gtest/gtest.h>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;

TEST(ConvexModel, CubeHasSixOutwardPlanes) {
  const ConvexModel m = convex_model(cube());
  ASSERT_TRUE(m.convex) << m.problem;
  ASSERT_EQ(m.planes.size(), 6u);
  for (const auto& p : m.planes) {
    EXPECT_EQ(p.triangles.size(), 2u);
    EXPECT_EQ(p.offset, Exact(1));  // unit normals, the cube [-1,1]^3
    int ones = 0;
    for (int i = 0; i < 3; ++i) ones += CGAL::abs(p.normal[i]) == 1;
    EXPECT_EQ(ones, 1);
  }
}

TEST(ConvexModel, WindingDoesNotMatter) {
  Scene s = cube();
  for (std::size_t i = 0; i < s.triangles.size(); i += 3) std::swap(s.triangles[i].v[1], s.triangles[i].v[2]);
  EXPECT_TRUE(convex_model(s).convex);
  EXPECT_TRUE(convex_model(tetrahedron()).convex);
}

TEST(ConvexModel, RandomHullsAreConvex) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Scene s = random_convex(seed, 12, 40);
    const ConvexModel m = convex_model(s);
    EXPECT_TRUE(m.convex) << m.problem;
  }
}

TEST(ConvexModel, NonConvexOpenDuplicatedAndFlatModelsAreRejected) {
  {  // An L-shaped prism: two boxes glued (their shared wall removed would still be non-convex).
    std::vector<Point3> v;
    std::vector<std::array<int, 3>> t;
    add_box(v, t, 0, 0, 0, 2, 1, 1);
    add_box(v, t, 0, 1, 0, 1, 2, 1);
    const ConvexModel m = convex_model(make_scene(v, t));
    EXPECT_FALSE(m.convex);
    EXPECT_NE(m.problem.find("both sides"), std::string::npos) << m.problem;
  }
  {  // Open: a cube without its last face.
    Scene s = cube();
    s.triangles.resize(10);
    const ConvexModel m = convex_model(s);
    EXPECT_FALSE(m.convex);
    EXPECT_NE(m.problem.find("not closed"), std::string::npos) << m.problem;
  }
  {  // Twice the cube: closed, every plane supporting, but the boundary is covered twice.
    Scene s = cube();
    const auto n = s.triangles.size();
    for (std::size_t i = 0; i < n; ++i) {
      auto t = s.triangles[i];
      t.id = static_cast<std::int64_t>(n + i);
      s.triangles.push_back(t);
    }
    const ConvexModel m = convex_model(s);
    EXPECT_FALSE(m.convex);
    EXPECT_NE(m.problem.find("exactly once"), std::string::npos) << m.problem;
  }
  {  // Flat: two triangles of a square, back to back.
    const ConvexModel m = convex_model(make_scene({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1, 2}, {0, 2, 1}}));
    EXPECT_FALSE(m.convex);
    EXPECT_NE(m.problem.find("flat"), std::string::npos) << m.problem;
  }
  {  // A T-junction: one cube face split into three triangles with a vertex on an edge of its neighbour.
    std::vector<Point3> v;
    std::vector<std::array<int, 3>> t;
    add_box(v, t, -1, -1, -1, 1, 1, 1);
    // Replace face z = -1 (triangles 0, 1: corners 0 2 3 1) by a fan around the midpoint of edge 0-1 ...
    v.push_back({0, -1, -1});  // 8: on edge (0,1), shared with face y = -1 which is not split
    t[0] = {0, 2, 8};
    t[1] = {8, 2, 3};
    t.push_back({8, 3, 1});
    const ConvexModel m = convex_model(make_scene(v, t));
    EXPECT_FALSE(m.convex);
    EXPECT_NE(m.problem.find("not closed"), std::string::npos) << m.problem;
  }
}

}  // namespace
