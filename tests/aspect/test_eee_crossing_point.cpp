// The EEE line checks of aspect/eee_crossing_point against hand-made lines: the transversal x = y = 0 of three
// pairwise skew edges meets no other edge, until a fourth triangle puts an edge across it (named in the one
// line); the double direction follows the line.
#include "aspect/eee_crossing_point.hpp"

#include "tests/aspect/aspect_test_models.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;

// Edges 0-1 (along x at z = 0), 3-4 (along y at z = 1) and 6-7 (along (1, 1, 0) at z = 2), all met by x = y = 0;
// with `fourth`, triangle 9-10-11 at z = 3 whose edge 9-10 crosses that line at (0, 0, 3).
Scene skew_edges(bool fourth) {
  std::vector<Point3> v{{-1, 0, 0}, {1, 0, 0}, {0, -3, 0}, {0, -1, 1}, {0, 1, 1}, {3, 0, 1}, {-1, -1, 2}, {1, 1, 2}, {2, -2, 2}};
  std::vector<std::array<int, 3>> t{{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  if (fourth) {
    v.insert(v.end(), {{-1, 1, 3}, {1, -1, 3}, {5, 5, 3}});
    t.push_back({9, 10, 11});
  }
  return make_scene(v, t);
}

DirectionEventArc family() {
  DirectionEventArc a;
  a.type = DirectionEventArc::Type::EEE;
  a.edges = {{{0, 1}, {3, 4}, {6, 7}}};
  return a;
}

TEST(EeeCrossingPoint, TransversalMeetingOnlyItsEdges) {
  const Scene s = skew_edges(false);
  EXPECT_EQ(eee_line_meets_only_its_edges(s, family(), RootNumber(Exact(1, 2))), "");
  EXPECT_EQ(eee_line_meets_only_its_edges(s, family(), RootNumber(Exact(1, 4))), "");
  const auto d = eee_direction_approx(s, family(), RootNumber(Exact(1, 2)));
  EXPECT_EQ(d[0], 0.0);
  EXPECT_EQ(d[1], 0.0);
  EXPECT_NE(d[2], 0.0);
}

TEST(EeeCrossingPoint, FourthEdgeOnTheLineIsNamed) {
  const Scene s = skew_edges(true);
  const std::string why = eee_line_meets_only_its_edges(s, family(), RootNumber(Exact(1, 2)));
  EXPECT_NE(why.find("meets the edge 9-10"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos);
  // Another line of the family (through (-1/2, 0, 0)) misses the fourth triangle's edges.
  EXPECT_EQ(eee_line_meets_only_its_edges(s, family(), RootNumber(Exact(1, 4))), "");
}

}  // namespace
