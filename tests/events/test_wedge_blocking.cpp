// wedge_blocked_interval on hand-built (mostly degenerate) configurations with known answers.
#include "events/wedge_blocking.hpp"

#include <gtest/gtest.h>

namespace exactvis {
namespace {

// Wedge: V = origin, E from A = (4, 0, 0) to B = (0, 4, 0); t = y / (x + y) along rays from V in z = 0.
const Point3 V{0, 0, 0}, A{4, 0, 0}, B{0, 4, 0};

std::optional<BlockedInterval> block(Point3 p, Point3 q, Point3 r) {
  return wedge_blocked_interval(V, A, B, {p, q, r}, {10, 11, 12});
}

TEST(WedgeBlocking, CrossingTriangleBlocksTheRaysItMeets) {
  // Vertical triangle crossing the plane z = 0 along the segment (1,1,0)-(2,1,0): t from 1/2 down to 1/3.
  const auto b = block({1, 1, -1}, {3, 1, 1}, {1, 1, 1});
  ASSERT_TRUE(b);
  // Crossing segment: edge (1,1,-1)-(3,1,1) meets z=0 at (2,1,0); edge (1,1,-1)-(1,1,1) at (1,1,0).
  EXPECT_EQ(b->lo.exact(), Exact(1, 3));
  EXPECT_EQ(b->hi.exact(), Exact(1, 2));
  EXPECT_EQ(b->lo_feature.kind, OccluderFeature::Kind::Edge);
  EXPECT_EQ(b->hi_feature.kind, OccluderFeature::Kind::Edge);
}

TEST(WedgeBlocking, TriangleOnOneSideBlocksNothing) {
  EXPECT_FALSE(block({1, 1, 1}, {2, 1, 1}, {1, 2, 3}));
}

TEST(WedgeBlocking, VertexTouchingThePlaneBlocksOneLine) {
  // Only the vertex (1, 2, 0) touches z = 0: the single line t = 2/3 (a VV line).
  const auto b = block({1, 2, 0}, {2, 3, 1}, {1, 4, 1});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->lo.exact(), Exact(2, 3));
  EXPECT_EQ(b->hi.exact(), Exact(2, 3));
  EXPECT_EQ(b->lo_feature.kind, OccluderFeature::Kind::Vertex);
  EXPECT_EQ(b->lo_feature.ids, std::vector<int>{10});
}

TEST(WedgeBlocking, TouchingOnlyAtVOrOnlyOnEBlocksNothing) {
  // Touches the plane only at V (open segments exclude V).
  EXPECT_FALSE(block({0, 0, 0}, {1, 1, 1}, {-1, 2, 1}));
  // Touches the plane only at a point of E (2, 2, 0) (open segments exclude P(t)).
  EXPECT_FALSE(block({2, 2, 0}, {3, 3, 1}, {2, 3, 1}));
  // Beyond E: meets the plane outside the closed wedge triangle.
  EXPECT_FALSE(block({3, 3, -1}, {5, 5, 1}, {3, 5, 1}));
}

TEST(WedgeBlocking, CoplanarTriangleInsideTheWedge) {
  const auto b = block({1, 1, 0}, {2, 1, 0}, {1, 2, 0});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->lo.exact(), Exact(1, 3));  // (2,1): 1/3
  EXPECT_EQ(b->hi.exact(), Exact(2, 3));  // (1,2): 2/3
}

TEST(WedgeBlocking, CoplanarTriangleCrossingAWedgeSideReachesTheEnd) {
  // Coplanar triangle straddling the side VA (y = 0): blocked from t = 0 to the ray through (1, 1).
  const auto b = block({1, -1, 0}, {2, -1, 0}, {1, 1, 0});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->lo.exact(), Exact(0));
  EXPECT_EQ(b->hi.exact(), Exact(1, 2));
  EXPECT_EQ(b->lo_feature.kind, OccluderFeature::Kind::WedgeSide);
}

TEST(WedgeBlocking, TriangleContainingVBlocksOnlyThroughItsInterior) {
  // Contains V at a vertex, crosses the plane along the ray towards (1, 1, 0): one line, t = 1/2.
  const auto b = block({0, 0, 0}, {2, 2, -1}, {2, 2, 1});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->lo.exact(), Exact(1, 2));
  EXPECT_EQ(b->hi.exact(), Exact(1, 2));
}

TEST(WedgeBlocking, TriangleMeetingEInItsInterior) {
  // Crosses the wedge plane along a segment from (1,1,0) to beyond E: clipped at E (t = 1/2 on both).
  const auto b = block({1, 1, -1}, {5, 5, 1}, {1, 1, 1});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->lo.exact(), Exact(1, 2));
  EXPECT_EQ(b->hi.exact(), Exact(1, 2));
}

}  // namespace
}  // namespace exactvis
