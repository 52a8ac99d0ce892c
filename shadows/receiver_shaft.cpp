#include "shadows/receiver_shaft.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <array>

namespace exactvis::shadows {
namespace {

// A plane through three of the hull's points with the sides on which no hull point lies ("outside"): a
// triangle with all three corners strictly on an outside side misses the hull.
struct SupportPlane {
  std::array<Point3, 3> p;
  bool pos_outside = false, neg_outside = false;
};

// The supporting planes through three of the six points (every triple: a non-supporting one has no outside
// side; a collinear triple gives orient3d = 0 everywhere and never separates). Exact.
std::vector<SupportPlane> support_planes(const std::array<Point3, 6>& pts) {
  std::vector<SupportPlane> out;
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j)
      for (int k = j + 1; k < 6; ++k) {
        bool pos = false, neg = false;
        for (int m = 0; m < 6; ++m) {
          if (m == i || m == j || m == k) continue;
          const Sign s = orient3d(pts[i], pts[j], pts[k], pts[m]);
          pos |= s == Sign::Positive;
          neg |= s == Sign::Negative;
        }
        if (pos && neg) continue;
        out.push_back({{pts[i], pts[j], pts[k]}, !pos, !neg});
      }
  return out;
}

// Whether the triangle t is strictly separated from the hull of `pts` by a supporting plane or by its own
// plane. Exact.
bool separated(const std::array<Point3, 3>& t, const std::vector<SupportPlane>& planes,
               const std::array<Point3, 6>& pts) {
  for (const auto& pl : planes) {
    const Sign s0 = orient3d(pl.p[0], pl.p[1], pl.p[2], t[0]);
    if (s0 == Sign::Zero) continue;
    if ((s0 == Sign::Positive && !pl.pos_outside) || (s0 == Sign::Negative && !pl.neg_outside)) continue;
    if (orient3d(pl.p[0], pl.p[1], pl.p[2], t[1]) == s0 && orient3d(pl.p[0], pl.p[1], pl.p[2], t[2]) == s0)
      return true;
  }
  // The triangle's own plane with all six hull points strictly on one side.
  const Sign s0 = orient3d(t[0], t[1], t[2], pts[0]);
  if (s0 == Sign::Zero) return false;
  for (int m = 1; m < 6; ++m)
    if (orient3d(t[0], t[1], t[2], pts[m]) != s0) return false;
  return true;
}

}  // namespace

ReceiverShaft receiver_shaft(const Scene& scene, const TriangleIndex& index, const std::vector<int>& light,
                             std::int64_t receiver) {
  ReceiverShaft shaft;
  shaft.receiver = receiver;
  const auto& rt = scene.triangles.at(receiver);
  for (int li : light) {
    const auto& lt = scene.triangles.at(li);
    const std::array<Point3, 6> pts{scene.corner(lt, 0), scene.corner(lt, 1), scene.corner(lt, 2),
                                    scene.corner(rt, 0), scene.corner(rt, 1), scene.corner(rt, 2)};
    Box3 box{pts[0], pts[0]};
    for (const auto& p : pts)
      for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], p[k]);
        box.hi[k] = std::max(box.hi[k], p[k]);
      }
    const std::vector<SupportPlane> planes = support_planes(pts);
    std::vector<std::int64_t> kept;
    std::vector<Box3> boxes;
    for (std::int64_t ti : index.triangles_meeting_box(box)) {
      ++shaft.box_candidates;
      if (ti == li) continue;
      const auto& t = scene.triangles[ti];
      const std::array<Point3, 3> tp{scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2)};
      if (separated(tp, planes, pts)) continue;
      kept.push_back(ti);
      boxes.push_back(triangle_box(scene, t));
    }
    shaft.candidates.push_back(std::move(kept));
    shaft.boxes.push_back(std::move(boxes));
  }
  return shaft;
}

}  // namespace exactvis::shadows
