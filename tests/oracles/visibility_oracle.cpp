#include "oracles/visibility_oracle.hpp"

#include <random>

namespace oracle {
namespace {

bool in_closed_polygon(const QVec& p, const std::vector<QVec>& poly) {
  for (std::size_t i = 1; i + 1 < poly.size(); ++i)
    if (oracle_point_in_closed_triangle(p, poly[0], poly[i], poly[i + 1])) return true;
  return false;
}

QVec random_in_polygon(const std::vector<QVec>& poly, std::mt19937_64& rng) {
  QVec acc{0, 0, 0};
  mpq_class total = 0;
  for (const auto& v : poly) {
    mpq_class w = 1 + static_cast<long>(rng() % 1000003);
    acc = acc + w * v;
    total += w;
  }
  return (1 / total) * acc;
}

QVec random_in_box(const QVec& lo, const QVec& hi, std::mt19937_64& rng) {
  auto coord = [&](const mpq_class& a, const mpq_class& b) -> mpq_class {
    mpq_class t = mpq_class(1 + static_cast<long>(rng() % 1000003)) / 1000005;
    return a + t * (b - a);
  };
  return {coord(lo.x, hi.x), coord(lo.y, hi.y), coord(lo.z, hi.z)};
}

// Exact bounding-box rejection: false when the segment's box and the triangle's box are disjoint.
bool boxes_overlap(const QVec& p, const QVec& q, const Triangle& t) {
  auto axis = [](const QVec& v, int k) -> const mpq_class& { return k == 0 ? v.x : (k == 1 ? v.y : v.z); };
  for (int k = 0; k < 3; ++k) {
    const mpq_class& a = axis(p, k);
    const mpq_class& b = axis(q, k);
    const mpq_class& lo_s = a < b ? a : b;
    const mpq_class& hi_s = a < b ? b : a;
    const mpq_class* lo_t = &axis(t[0], k);
    const mpq_class* hi_t = lo_t;
    for (int c = 1; c < 3; ++c) {
      if (axis(t[c], k) < *lo_t) lo_t = &axis(t[c], k);
      if (axis(t[c], k) > *hi_t) hi_t = &axis(t[c], k);
    }
    if (hi_s < *lo_t || *hi_t < lo_s) return false;
  }
  return true;
}

}  // namespace

bool witness_is_valid(const std::vector<Triangle>& scene, std::size_t target, const Source& source, const QVec& p,
                      const QVec& q, std::string* why) {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (source.is_box) {
    if (!oracle_point_in_closed_box(p, source.lo, source.hi)) return fail("p is not in the view cell");
  } else if (!in_closed_polygon(p, source.polygon)) {
    return fail("p is not on the source polygon");
  }
  const Triangle& t = scene[target];
  if (!oracle_point_in_triangle_relative_interior(q, t[0], t[1], t[2]))
    return fail("q is not in the relative interior of the target");
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (i == target || !boxes_overlap(p, q, scene[i])) continue;
    if (oracle_open_segment_meets_closed_triangle(p, q, scene[i][0], scene[i][1], scene[i][2]))
      return fail("the segment meets triangle " + std::to_string(i));
  }
  return true;
}

std::optional<std::pair<QVec, QVec>> find_robust_free_segment(const std::vector<Triangle>& scene, std::size_t target,
                                                              const Source& source, int samples,
                                                              unsigned long seed) {
  std::mt19937_64 rng(seed);
  const Triangle& t = scene[target];
  const std::vector<QVec> tpoly{t[0], t[1], t[2]};
  for (int s = 0; s < samples; ++s) {
    const QVec p = source.is_box ? random_in_box(source.lo, source.hi, rng) : random_in_polygon(source.polygon, rng);
    const QVec q = random_in_polygon(tpoly, rng);
    bool ok = true;
    for (std::size_t i = 0; i < scene.size() && ok; ++i) {
      if (i == target) continue;
      const auto& o = scene[i];
      if (!boxes_overlap(p, q, o)) continue;
      if (oracle_open_segment_meets_closed_triangle(p, q, o[0], o[1], o[2]) ||
          oracle_point_in_closed_triangle(p, o[0], o[1], o[2]) || oracle_point_in_closed_triangle(q, o[0], o[1], o[2]))
        ok = false;
    }
    if (ok) return std::make_pair(p, q);
  }
  return std::nullopt;
}

}  // namespace oracle
