// OccluderIndex::triangles_in_box against brute force (necessary conditions only): every triangle with a
// corner in the closed box is returned, and no triangle whose bounding box is disjoint from the box is.
#include "events/occluder_index.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace exactvis {
namespace {

bool corner_inside(const Point3& p, const Box3& b) {
  return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

bool bbox_disjoint(const std::array<Point3, 3>& c, const Box3& b) {
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::min({c[0][axis], c[1][axis], c[2][axis]});
    const double hi = std::max({c[0][axis], c[1][axis], c[2][axis]});
    if (hi < b.lo[axis] || lo > b.hi[axis]) return true;
  }
  return false;
}

TEST(OccluderIndex, TrianglesInBoxBruteForce) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-10, 10), size(0.1, 4);
  for (int round = 0; round < 20; ++round) {
    Scene s;
    for (int k = 0; k < 200; ++k) {
      const int b = static_cast<int>(s.vertices.size());
      const Point3 c{u(rng), u(rng), u(rng)};
      for (int q = 0; q < 3; ++q) s.vertices.push_back({c.x + size(rng), c.y - size(rng), c.z + size(rng) - 2});
      s.triangles.push_back({k, {b, b + 1, b + 2}, 0});
    }
    s.objects.push_back({"test"});
    const OccluderIndex index(s);
    for (int q = 0; q < 20; ++q) {
      const Point3 a{u(rng), u(rng), u(rng)}, d{u(rng), u(rng), u(rng)};
      const Box3 box{{std::min(a.x, d.x), std::min(a.y, d.y), std::min(a.z, d.z)},
                     {std::max(a.x, d.x), std::max(a.y, d.y), std::max(a.z, d.z)}};
      const std::vector<int> got = index.triangles_in_box(box);
      EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
      for (int ti = 0; ti < static_cast<int>(s.triangles.size()); ++ti) {
        const auto& t = s.triangles[ti];
        const std::array<Point3, 3> c{s.corner(t, 0), s.corner(t, 1), s.corner(t, 2)};
        const bool returned = std::binary_search(got.begin(), got.end(), ti);
        if (corner_inside(c[0], box) || corner_inside(c[1], box) || corner_inside(c[2], box))
          EXPECT_TRUE(returned) << "triangle with a corner in the box not returned";
        if (bbox_disjoint(c, box)) EXPECT_FALSE(returned) << "triangle far from the box returned";
      }
    }
  }
}

}  // namespace
}  // namespace exactvis
