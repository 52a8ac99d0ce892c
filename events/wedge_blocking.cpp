#include "events/wedge_blocking.hpp"

#include "kernel/predicates.hpp"

namespace exactvis {
namespace {

// A point of the wedge plane in homogeneous coordinates: X - V = (a (A - V) + b (B - V)) / (w |n|^2), w > 0,
// with the occluder feature it lies on. Ring arithmetic only (exact, no division).
struct PlanePoint {
  Ring a, b, w;
  OccluderFeature feature;
};

// Sutherland-Hodgman clip of a convex (possibly degenerate: 1 or 2 points) polygon by f(x) >= 0, f linear in
// the homogeneous coordinates (so its sign is the sign at the point, as w > 0).
template <class F>
std::vector<PlanePoint> clip(const std::vector<PlanePoint>& poly, F f, const OccluderFeature& on_line) {
  std::vector<PlanePoint> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const PlanePoint& p = poly[i];
    const PlanePoint& q = poly[(i + 1) % n];
    const Ring fp = f(p), fq = f(q);
    const int sp = CGAL::sign(fp), sq = CGAL::sign(fq);
    if (sp >= 0) out.push_back(p);
    if (sp * sq < 0) {
      // r = fp q - fq p has f(r) = 0; its w is positive when fp > 0 > fq, else negate.
      PlanePoint r{fp * q.a - fq * p.a, fp * q.b - fq * p.b, fp * q.w - fq * p.w, on_line};
      if (sp < 0) r.a = -r.a, r.b = -r.b, r.w = -r.w;
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace

std::optional<BlockedInterval> wedge_blocked_interval(const Point3& v, const Point3& a, const Point3& b,
                                                      const std::array<Point3, 3>& p,
                                                      const std::array<int, 3>& ids) {
  // Cheap exact rejection: all corners strictly on one side of the wedge plane.
  std::array<int, 3> h{};
  for (int k = 0; k < 3; ++k) h[k] = to_int(orient3d(v, a, b, p[k]));
  if ((h[0] > 0 && h[1] > 0 && h[2] > 0) || (h[0] < 0 && h[1] < 0 && h[2] < 0)) return std::nullopt;

  auto ring = [](const Point3& q) { return Vec3<Ring>(Ring(q.x), Ring(q.y), Ring(q.z)); };
  const Vec3<Ring> V = ring(v);
  const Vec3<Ring> av = ring(a) - V, bv = ring(b) - V;
  const Vec3<Ring> n = cross(av, bv);
  const Ring nn = dot(n, n);
  std::array<Ring, 3> alpha, beta, hx;
  for (int k = 0; k < 3; ++k) {
    const Vec3<Ring> x = ring(p[k]) - V;
    alpha[k] = dot(cross(x, bv), n);
    beta[k] = dot(cross(av, x), n);
    hx[k] = dot(n, x);
  }
  // C = T intersected with the wedge plane, as at most 3 points with their features.
  std::vector<PlanePoint> poly;
  if (h[0] == 0 && h[1] == 0 && h[2] == 0) {
    for (int k = 0; k < 3; ++k)
      poly.push_back({alpha[k], beta[k], Ring(1), {OccluderFeature::Kind::Vertex, {ids[k]}}});
  } else {
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      if (h[k] == 0) poly.push_back({alpha[k], beta[k], Ring(1), {OccluderFeature::Kind::Vertex, {ids[k]}}});
      if (h[k] * h[j] < 0) {
        // X = (hk Pj - hj Pk) / (hk - hj)
        PlanePoint x{hx[k] * alpha[j] - hx[j] * alpha[k], hx[k] * beta[j] - hx[j] * beta[k], hx[k] - hx[j],
                     {OccluderFeature::Kind::Edge, {ids[k], ids[j]}}};
        if (CGAL::sign(x.w) < 0) x.a = -x.a, x.b = -x.b, x.w = -x.w;
        poly.push_back(std::move(x));
      }
    }
  }
  if (poly.empty()) return std::nullopt;
  const OccluderFeature side{OccluderFeature::Kind::WedgeSide, {}};
  const OccluderFeature face{OccluderFeature::Kind::Face, {ids[0], ids[1], ids[2]}};
  poly = clip(poly, [](const PlanePoint& q) { return q.a; }, side);
  if (poly.empty()) return std::nullopt;
  poly = clip(poly, [](const PlanePoint& q) { return q.b; }, side);
  if (poly.empty()) return std::nullopt;
  poly = clip(poly, [&](const PlanePoint& q) { return nn * q.w - q.a - q.b; }, face);
  if (poly.empty()) return std::nullopt;

  // The open segments exclude V (a + b = 0) and E (a + b = |n|^2 w). Q minus those is empty iff Q is {V} or
  // lies on E; otherwise the t-range of Q' is that of Q's vertices other than V (t is constant along rays
  // from V, so an edge leaving V has the t of its other end).
  bool all_on_e = true, any_not_v = false;
  for (const auto& q : poly) {
    const Ring s = q.a + q.b;
    if (CGAL::sign(nn * q.w - s) != 0) all_on_e = false;
    if (CGAL::sign(s) != 0) any_not_v = true;
  }
  if (all_on_e || !any_not_v) return std::nullopt;
  std::optional<BlockedInterval> r;
  for (const auto& q : poly) {
    const Ring s = q.a + q.b;
    if (CGAL::sign(s) == 0) continue;
    const EvParameter t(q.b, s);  // t = beta / (alpha + beta)
    if (!r) {
      r = BlockedInterval{t, t, q.feature, q.feature};
      continue;
    }
    if (t < r->lo) r->lo = t, r->lo_feature = q.feature;
    if (t > r->hi) r->hi = t, r->hi_feature = q.feature;
  }
  return r;
}

}  // namespace exactvis
