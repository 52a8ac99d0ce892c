// Pictures of partitions: every triangle of the sphere gets a region of dimension 2 (the open faces cover
// the sphere up to curves), each 2-dimensional region shows up, one boundary curve per great circle; the
// plane picture labels points inside the model's section -1.
#include "aspect/partition_picture.hpp"

#include "aspect/convex_aspect_graph.hpp"
#include "aspect/orthographic_aspect_graph.hpp"
#include "tests/aspect/aspect_test_models.hpp"

#include <gtest/gtest.h>

#include <set>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;

TEST(PartitionPicture, SphereOfTheCube) {
  const Scene s = cube();
  const ConvexModel m = convex_model(s);
  const AspectGraph3 g = convex_aspect_graph(s, m, ViewModel::Orthographic);
  const PartitionPicture p = sphere_picture(m, g, 3);
  EXPECT_EQ(p.triangles.size(), 8u * 64);
  std::set<std::int64_t> seen;
  for (auto r : p.triangle_region) {
    ASSERT_GE(r, 0);
    seen.insert(r);
  }
  for (std::size_t r = 0; r < g.regions.size(); ++r) {
    if (g.regions[r].dimension == 2) {
      EXPECT_TRUE(seen.count(static_cast<std::int64_t>(r)));
    }
  }
  EXPECT_EQ(p.curves.size(), 3u);  // three great circles for six faces
}

TEST(PartitionPicture, PlaneThroughTheCube) {
  const Scene s = cube();
  const ConvexModel m = convex_model(s);
  const AspectGraph3 g = convex_aspect_graph_on_plane(s, m, Vec3<Exact>(0, 0, 1), Exact(0));
  const PartitionPicture p = plane_picture(m, g, 0, -3, -3, 3, 3, 30);
  std::set<std::int64_t> seen(p.triangle_region.begin(), p.triangle_region.end());
  EXPECT_TRUE(seen.count(-1));               // the section of the cube
  EXPECT_EQ(seen.size(), g.regions.size() + 1);  // and the 8 regions around it
  EXPECT_EQ(p.curves.size(), 4u);            // x = +-1, y = +-1
}

// Non-convex (L-prism): every sphere triangle gets a region, and at every 97th triangle's centroid the
// independent slab oracle sees the region's aspect.
TEST(PartitionPicture, SphereOfTheLPrismByCells) {
  const Scene s = l_prism();
  const AspectGraph3 g = orthographic_aspect_graph(s, closed_solid_fronts(s));
  const PartitionPicture pic = sphere_picture_of_cells(g, 3);
  ASSERT_EQ(pic.triangle_region.size(), pic.triangles.size());
  const auto model = oracle_model(s);
  for (std::size_t i = 0; i < pic.triangles.size(); ++i) {
    ASSERT_GE(pic.triangle_region[i], 0);
    if (i % 97) continue;
    const auto& t = pic.triangles[i];
    const Point3 &a = pic.points[t[0]], &b = pic.points[t[1]], &c = pic.points[t[2]];
    std::vector<std::int64_t> ids;
    for (int k : oracle::direction_aspect(model, oracle::qvec(a.x + b.x + c.x, a.y + b.y + c.y, a.z + b.z + c.z)))
      ids.push_back(s.triangles[k].id);
    EXPECT_EQ(ids, g.regions[pic.triangle_region[i]].aspect) << i;
  }
  EXPECT_EQ(pic.curves.size(), g.circles.size());
}

}  // namespace
