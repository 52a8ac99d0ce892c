#include "kernel/scene.hpp"

#include <algorithm>
#include <limits>

namespace exactvis {

std::int64_t Scene::index_of_id(std::int64_t id) const {
  auto it = std::lower_bound(triangles.begin(), triangles.end(), id,
                             [](const SceneTriangle& t, std::int64_t v) { return t.id < v; });
  if (it == triangles.end() || it->id != id) return -1;
  return it - triangles.begin();
}

Box3 intersection(const Box3& a, const Box3& b) {
  return {{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y), std::max(a.lo.z, b.lo.z)},
          {std::min(a.hi.x, b.hi.x), std::min(a.hi.y, b.hi.y), std::min(a.hi.z, b.hi.z)}};
}

Box3 triangle_box(const Scene& scene, const SceneTriangle& t) {
  Box3 b{scene.corner(t, 0), scene.corner(t, 0)};
  for (int c = 1; c < 3; ++c)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], scene.corner(t, c)[k]);
      b.hi[k] = std::max(b.hi[k], scene.corner(t, c)[k]);
    }
  return b;
}

Box3 bounding_box(const Scene& scene) {
  const double inf = std::numeric_limits<double>::infinity();
  Box3 b{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (const auto& t : scene.triangles)
    for (int k = 0; k < 3; ++k) {
      const Point3& p = scene.corner(t, k);
      b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
      b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
    }
  return b;
}

}  // namespace exactvis
