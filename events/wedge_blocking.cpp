#include "events/wedge_blocking.hpp"

#include "kernel/predicates.hpp"

namespace exactvis {
namespace {

// A point of the wedge plane in coordinates X - V = alpha a + beta b, with the occluder feature it lies on.
struct PlanePoint {
  Exact alpha, beta;
  OccluderFeature feature;
};

// Sutherland-Hodgman clip of a convex (possibly degenerate: 1 or 2 points) polygon by f(x) >= 0, f affine.
template <class F>
std::vector<PlanePoint> clip(const std::vector<PlanePoint>& poly, F f, const OccluderFeature& on_line) {
  std::vector<PlanePoint> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const PlanePoint& p = poly[i];
    const PlanePoint& q = poly[(i + 1) % n];
    const Exact fp = f(p), fq = f(q);
    if (CGAL::sign(fp) >= 0) out.push_back(p);
    if ((CGAL::sign(fp) < 0 && CGAL::sign(fq) > 0) || (CGAL::sign(fp) > 0 && CGAL::sign(fq) < 0)) {
      const Exact lambda = fp / (fp - fq);
      out.push_back({p.alpha + lambda * (q.alpha - p.alpha), p.beta + lambda * (q.beta - p.beta), on_line});
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

  const Vec3<Exact> V = to_rational(v);
  const Vec3<Exact> av = to_rational(a) - V, bv = to_rational(b) - V;
  const Vec3<Exact> n = cross(av, bv);
  const Exact nn = dot(n, n);
  std::array<Exact, 3> alpha, beta, hx;
  for (int k = 0; k < 3; ++k) {
    const Vec3<Exact> x = to_rational(p[k]) - V;
    alpha[k] = dot(cross(x, bv), n) / nn;
    beta[k] = dot(cross(av, x), n) / nn;
    hx[k] = dot(n, x);
  }
  // C = T intersected with the wedge plane, as at most 3 points with their features.
  std::vector<PlanePoint> poly;
  if (h[0] == 0 && h[1] == 0 && h[2] == 0) {
    for (int k = 0; k < 3; ++k) poly.push_back({alpha[k], beta[k], {OccluderFeature::Kind::Vertex, {ids[k]}}});
  } else {
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      if (h[k] == 0) poly.push_back({alpha[k], beta[k], {OccluderFeature::Kind::Vertex, {ids[k]}}});
      if (h[k] * h[j] < 0) {
        const Exact lambda = hx[k] / (hx[k] - hx[j]);
        poly.push_back({alpha[k] + lambda * (alpha[j] - alpha[k]), beta[k] + lambda * (beta[j] - beta[k]),
                        {OccluderFeature::Kind::Edge, {ids[k], ids[j]}}});
      }
    }
  }
  if (poly.empty()) return std::nullopt;
  const OccluderFeature side{OccluderFeature::Kind::WedgeSide, {}};
  const OccluderFeature face{OccluderFeature::Kind::Face, {ids[0], ids[1], ids[2]}};
  poly = clip(poly, [](const PlanePoint& q) { return q.alpha; }, side);
  if (poly.empty()) return std::nullopt;
  poly = clip(poly, [](const PlanePoint& q) { return q.beta; }, side);
  if (poly.empty()) return std::nullopt;
  poly = clip(poly, [](const PlanePoint& q) { return Exact(1) - q.alpha - q.beta; }, face);
  if (poly.empty()) return std::nullopt;

  // The open segments exclude V (alpha + beta = 0) and E (alpha + beta = 1). Q minus those is empty iff Q
  // is {V} or lies on E; otherwise the t-range of Q' is that of Q's vertices other than V (t is constant
  // along rays from V, so an edge leaving V has the t of its other end).
  bool all_on_e = true, any_not_v = false;
  for (const auto& q : poly) {
    const Exact s = q.alpha + q.beta;
    if (s != 1) all_on_e = false;
    if (CGAL::sign(s) != 0) any_not_v = true;
  }
  if (all_on_e || !any_not_v) return std::nullopt;
  std::optional<BlockedInterval> r;
  for (const auto& q : poly) {
    const Exact s = q.alpha + q.beta;
    if (CGAL::sign(s) == 0) continue;
    const Exact t = q.beta / s;
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
