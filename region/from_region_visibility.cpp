#include "region/from_region_visibility.hpp"

#include "kernel/segment_triangle_intersection.hpp"
#include "region/polyhedral_cone6.hpp"
#include "region/real_line_test.hpp"
#include "region/stabbing_pair.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>

namespace exactvis::region {
namespace {

std::array<RationalPoint3, 3> triangle_points(const Scene& scene, std::int64_t index) {
  const auto& t = scene.triangles[index];
  return {to_rational(scene.corner(t, 0)), to_rational(scene.corner(t, 1)), to_rational(scene.corner(t, 2))};
}

// A double box containing all the points (interval bounds of the exact coordinates).
Box3 enclosing_box(const std::vector<RationalPoint3>& pts) {
  const double inf = std::numeric_limits<double>::infinity();
  Box3 b{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (const auto& p : pts)
    for (int k = 0; k < 3; ++k) {
      const auto iv = enclosing_interval(p[k]);
      b.lo[k] = std::min(b.lo[k], iv.first);
      b.hi[k] = std::max(b.hi[k], iv.second);
    }
  return b;
}

// Random strictly positive barycentric weights for a polygon's vertices.
std::vector<long> random_weights(std::size_t n, std::mt19937_64& rng) {
  std::vector<long> w(n);
  for (auto& x : w) x = 1 + static_cast<long>(rng() % (1u << 20));
  return w;
}

// The point with those weights: exact (rational, in the relative interior of the polygon) ...
RationalPoint3 weighted_point(const Polygon3& poly, const std::vector<long>& w) {
  RationalPoint3 acc{Exact(0), Exact(0), Exact(0)};
  long total = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    acc = acc + Exact(w[i]) * poly[i];
    total += w[i];
  }
  const Exact t(total);
  return {acc.x / t, acc.y / t, acc.z / t};
}

// ... and its double approximation (for heuristics only: sample ordering).
Point3 weighted_point_approx(const std::vector<Point3>& poly, const std::vector<long>& w) {
  Point3 acc{0, 0, 0};
  double total = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    acc = acc + static_cast<double>(w[i]) * poly[i];
    total += static_cast<double>(w[i]);
  }
  return {acc.x / total, acc.y / total, acc.z / total};
}

std::vector<Point3> approx(const Polygon3& poly) {
  std::vector<Point3> out;
  for (const auto& p : poly) out.push_back({CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)});
  return out;
}

RationalPoint3 random_interior_point(const Polygon3& poly, std::mt19937_64& rng) {
  return weighted_point(poly, random_weights(poly.size(), rng));
}

struct Occluder {
  std::int64_t triangle = -1;
  std::array<RationalPoint3, 3> corners;
  std::array<Point3, 3> corners_d;  // the same corners as input doubles
  std::vector<IntVec6> edges;  // functionals of the clipped polygon's edges, in loop order
  int blocked_samples = 0;
};

// Planes through an edge of one polygon and a vertex of the other that support conv(S' u T'), plus the two
// polygon planes; each oriented so the hull is on the side value >= 0.
std::vector<Plane3> shaft_planes(const StabbingPair& pair) {
  std::vector<RationalPoint3> pts = pair.source;
  pts.insert(pts.end(), pair.target.begin(), pair.target.end());
  std::vector<Plane3> planes{pair.source_plane, pair.target_plane};
  auto consider = [&](const Polygon3& edges_of, const Polygon3& vertices_of) {
    for (std::size_t i = 0; i < edges_of.size(); ++i) {
      const auto& a = edges_of[i];
      const auto& b = edges_of[(i + 1) % edges_of.size()];
      for (const auto& c : vertices_of) {
        if (collinear(a, b, c)) continue;
        const Plane3 pl = plane_through(a, b, c);
        bool pos = false, neg = false;
        for (const auto& p : pts) {
          const int s = CGAL::sign(pl.value(p));
          pos |= s > 0;
          neg |= s < 0;
        }
        if (pos && neg) continue;
        planes.push_back(neg ? pl.flipped() : pl);
      }
    }
  };
  consider(pair.source, pair.target);
  consider(pair.target, pair.source);
  return planes;
}

// A shaft plane with its coefficients also as intervals, for a filtered side test without conversions.
struct FilteredPlane {
  Plane3 exact;
  Interval a, b, c, d;
  explicit FilteredPlane(const Plane3& p)
      : exact(p), a(enclosing_interval(p.normal.x)), b(enclosing_interval(p.normal.y)),
        c(enclosing_interval(p.normal.z)), d(enclosing_interval(p.offset)) {}
  // Exact: is plane.value(x) > 0?
  bool positive(const Point3& x) const {
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval v = a * x.x + b * x.y + c * x.z - d;
      if (v.inf() > 0) return true;
      if (v.sup() <= 0) return false;
    }
    return plane_side(exact, x) == Sign::Positive;
  }
};

std::vector<Occluder> prepare_occluders(const Scene& scene, const std::vector<std::int64_t>& candidates,
                                        std::int64_t target, const StabbingPair& pair) {
  std::vector<FilteredPlane> planes;
  for (const auto& p : shaft_planes(pair)) planes.emplace_back(p);
  std::vector<Occluder> out;
  for (const std::int64_t idx : candidates) {
    if (idx == target) continue;
    const auto& st = scene.triangles[idx];
    bool culled = false;
    for (const auto& pl : planes) {
      // Entirely on the closed outer side of a supporting plane: meets the shaft at most in that plane,
      // which only a measure-zero set of stabbing segments touches (docs/theory.md §5.2).
      if (!pl.positive(scene.corner(st, 0)) && !pl.positive(scene.corner(st, 1)) && !pl.positive(scene.corner(st, 2))) {
        culled = true;
        break;
      }
    }
    if (culled) continue;
    const auto tri = triangle_points(scene, idx);
    Polygon3 clipped = clip_polygon({tri[0], tri[1], tri[2]}, pair.source_plane);
    clipped = clip_polygon(clipped, pair.target_plane);
    if (is_degenerate(clipped)) continue;
    if (lies_in_plane(clipped, pair.source_plane) || lies_in_plane(clipped, pair.target_plane)) continue;
    Occluder occ;
    occ.triangle = idx;
    occ.corners = tri;
    occ.corners_d = {scene.corner(st, 0), scene.corner(st, 1), scene.corner(st, 2)};
    for (std::size_t i = 0; i < clipped.size(); ++i)
      occ.edges.push_back(side_functional(line_through(clipped[i], clipped[(i + 1) % clipped.size()])));
    out.push_back(std::move(occ));
  }
  return out;
}

// --- witness construction -------------------------------------------------------------------------------

mpq_class q_at(const RatVec6& x) { return x[0] * x[3] + x[1] * x[4] + x[2] * x[5]; }

RatVec6 lerp(const IntVec6& a, const IntVec6& b, const mpq_class& t) {
  RatVec6 x;
  for (int k = 0; k < 6; ++k) x[k] = (1 - t) * a[k] + t * b[k];
  return x;
}

// The real line (d, m - (d.m / d.d) d) next to a 6-vector with d != 0.
std::optional<RatVec6> realify(const RatVec6& x) {
  const mpq_class dd = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  if (sgn(dd) == 0) return std::nullopt;
  const mpq_class f = q_at(x) / dd;
  RatVec6 y = x;
  for (int k = 0; k < 3; ++k) y[3 + k] -= f * x[k];
  return y;
}

RationalPoint3 meet_plane(const RatVec6& line, const Plane3& plane) {
  const Vec3<Exact> d{Exact(line[0].get_mpq_t()), Exact(line[1].get_mpq_t()), Exact(line[2].get_mpq_t())};
  const Vec3<Exact> m{Exact(line[3].get_mpq_t()), Exact(line[4].get_mpq_t()), Exact(line[5].get_mpq_t())};
  const Exact dd = dot(d, d);
  const Vec3<Exact> dm = cross(d, m);
  const RationalPoint3 p0{dm.x / dd, dm.y / dd, dm.z / dd};  // point of the line closest to the origin
  const Exact t = (plane.offset - dot(plane.normal, p0)) / dot(plane.normal, d);
  return p0 + t * d;
}

IntVec6 scaled_sum(const IntVec6& a, unsigned shift, const IntVec6& c) {
  IntVec6 v;
  for (int k = 0; k < 6; ++k) v[k] = (a[k] << shift) + c[k];
  return v;
}

// A point of the open cone K with q of sign `s`, next to the closure point `x` (q(x) has sign s).
IntVec6 push_inside(const IntVec6& x, const IntVec6& interior, int s) {
  for (unsigned shift = 1;; shift += 4) {
    IntVec6 y = scaled_sum(x, shift, interior);
    if (sgn(plucker_form(y)) == s) return y;
  }
}

// Real lines of the open cone K, found between a positive and a negative point; each candidate is a
// directed line crossing relint S' and relint T' (it satisfies every constraint strictly).
struct LineCandidate {
  RationalPoint3 p, q;
};

std::optional<LineCandidate> real_line_in_cone(const PolyhedralCone6& cone, const RealLineTest& test,
                                               const StabbingPair& pair, std::mt19937_64& rng) {
  IntVec6 c = interior_point(cone);
  if (!cone.rays.empty()) {  // vary the interior point between attempts
    const auto& r = cone.rays[rng() % cone.rays.size()];
    const long factor = 1 + static_cast<long>(rng() % 7);
    for (int k = 0; k < 6; ++k) c[k] += r[k] * factor;
  }
  const IntVec6 a = push_inside(test.positive_point, c, +1);
  const IntVec6 b = push_inside(test.negative_point, c, -1);
  mpq_class lo = 0, hi = 1;
  for (int iter = 1; iter <= 2048; ++iter) {
    const mpq_class mid = (lo + hi) / 2;
    const int s = sgn(q_at(lerp(a, b, mid)));
    if (s == 0) {
      lo = hi = mid;
    } else if (s > 0) {
      lo = mid;
    } else {
      hi = mid;
    }
    if (iter % 16 != 0 && s != 0) continue;
    const auto line = realify(lerp(a, b, lo));
    if (!line) continue;
    if (!in_open_cone(cone, to_integer(*line))) {
      if (s == 0) return std::nullopt;
      continue;
    }
    return LineCandidate{meet_plane(*line, pair.source_plane), meet_plane(*line, pair.target_plane)};
  }
  return std::nullopt;
}

// --- the CSG --------------------------------------------------------------------------------------------

struct Piece {
  PolyhedralCone6 cone;
  RealLineTest test;
  std::size_t next = 0;  // first occluder not yet subtracted
};

class PairQuery {
 public:
  PairQuery(const Scene& scene, const std::vector<std::int64_t>& candidates, std::int64_t target,
            const StabbingPair& pair, const VisibilityOptions& options, VisibilityStats& stats)
      : scene_(scene), candidates_(candidates), target_(target), pair_(pair), options_(options), stats_(stats),
        rng_(options.seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(target)) {}

  std::optional<Witness> run() {
    occluders_ = prepare_occluders(scene_, candidates_, target_, pair_);
    stats_.occluders_considered += static_cast<std::int64_t>(occluders_.size());
    if (auto w = sample()) {
      stats_.accepted_by_sampling = true;
      return w;
    }
    std::stable_sort(occluders_.begin(), occluders_.end(),
                     [](const Occluder& x, const Occluder& y) { return x.blocked_samples > y.blocked_samples; });
    effective_.assign(occluders_.size(), false);

    std::optional<PolyhedralCone6> k0 = whole_space_cone();
    for (const auto& e : pair_.edge_lines) {
      k0 = intersect_open_halfspace(*k0, side_functional(e));
      if (!k0) return std::nullopt;
    }
    Piece first{*k0, test(*k0), 0};
    if (!first.test.has_real_lines) return std::nullopt;
    std::vector<Piece> stack{std::move(first)};
    while (!stack.empty()) {
      stats_.cones_alive_max = std::max<std::int64_t>(stats_.cones_alive_max, static_cast<std::int64_t>(stack.size()));
      Piece piece = std::move(stack.back());
      stack.pop_back();
      std::size_t j = piece.next;
      while (j < occluders_.size() && !touches(piece.cone, occluders_[j])) ++j;
      if (j == occluders_.size()) {
        if (auto w = witness_from(piece)) return w;
        throw std::logic_error("from-region query: a cone with real lines yielded no free witness segment");
      }
      if (!effective_[j]) {
        effective_[j] = true;
        ++stats_.effective_occluders;
      }
      std::vector<Piece> outside;
      split(piece.cone, piece.test, occluders_[j], 0, false, false, outside);
      for (auto& p : outside) {
        p.next = j + 1;
        stack.push_back(std::move(p));
      }
    }
    return std::nullopt;
  }

 private:
  RealLineTest test(const PolyhedralCone6& cone) {
    ++stats_.real_line_tests;
    RealLineTest t = test_real_lines(cone);
    stats_.face_tests += t.faces_examined;
    return t;
  }

  // Could some line of the cone meet the occluder (all edge sides >= 0, or all <= 0)?
  bool touches(const PolyhedralCone6& cone, const Occluder& occ) const {
    bool plus = true, minus = true;
    for (const auto& w : occ.edges) {
      const HalfspaceRelation r = relation_to_halfspace(cone, w);
      if (r == HalfspaceRelation::Outside) plus = false;
      if (r == HalfspaceRelation::Inside) minus = false;
      if (!plus && !minus) return false;
    }
    return true;
  }

  // Pieces of cone minus the occluder's line set: lines that pass the edges with mixed signs.
  void split(const PolyhedralCone6& cone, const RealLineTest& t, const Occluder& occ, std::size_t k, bool pos,
             bool neg, std::vector<Piece>& out) {
    if (pos && neg) {
      out.push_back(Piece{cone, t, 0});
      return;
    }
    if (k == occ.edges.size()) return;  // every edge passed on one side: the lines hit the occluder
    const IntVec6& w = occ.edges[k];
    const HalfspaceRelation r = relation_to_halfspace(cone, w);
    if (r == HalfspaceRelation::Inside) return split(cone, t, occ, k + 1, true, neg, out);
    if (r == HalfspaceRelation::Outside) return split(cone, t, occ, k + 1, pos, true, out);
    for (int s : {+1, -1}) {
      IntVec6 ws = w;
      if (s < 0)
        for (auto& c : ws) c = -c;
      ++stats_.splits;
      auto part = intersect_open_halfspace(cone, ws);
      if (!part) continue;
      ++stats_.cones_created;
      RealLineTest pt = test(*part);
      if (!pt.has_real_lines) continue;
      split(*part, pt, occ, k + 1, pos || s > 0, neg || s < 0, out);
    }
  }

  std::optional<Witness> witness_from(const Piece& piece) {
    for (int attempt = 0; attempt < 64; ++attempt) {
      auto cand = real_line_in_cone(piece.cone, piece.test, pair_, rng_);
      if (!cand) continue;
      // Free of every subtracted occluder by construction; re-check against all candidates, which also
      // covers the measure-zero blockers the CSG may ignore (docs/theory.md §5.4).
      if (segment_is_free(scene_, candidates_, cand->p, cand->q, target_)) return Witness{cand->p, cand->q};
    }
    return std::nullopt;
  }

  // Sample segments are cast with double endpoints (the counts only order the occluders); a sample that
  // looks free is redone with its exact rational endpoints and accepted only after the exact check.
  std::optional<Witness> sample() {
    const auto src = approx(pair_.source), dst = approx(pair_.target);
    for (int s = 0; s < options_.samples; ++s) {
      ++stats_.samples_cast;
      const auto ws = random_weights(src.size(), rng_), wt = random_weights(dst.size(), rng_);
      const Point3 p = weighted_point_approx(src, ws), q = weighted_point_approx(dst, wt);
      bool free = true;
      for (auto& occ : occluders_)
        if (open_segment_meets_closed_triangle(p, q, occ.corners_d[0], occ.corners_d[1], occ.corners_d[2])) {
          ++occ.blocked_samples;
          free = false;
        }
      if (!free) continue;
      const RationalPoint3 pe = weighted_point(pair_.source, ws), qe = weighted_point(pair_.target, wt);
      if (segment_is_free(scene_, candidates_, pe, qe, target_)) return Witness{pe, qe};
    }
    return std::nullopt;
  }

  const Scene& scene_;
  const std::vector<std::int64_t>& candidates_;
  std::int64_t target_;
  const StabbingPair& pair_;
  const VisibilityOptions& options_;
  VisibilityStats& stats_;
  std::mt19937_64 rng_;
  std::vector<Occluder> occluders_;
  std::vector<bool> effective_;
};

std::vector<RationalPoint3> with_triangle(const Polygon3& poly, const std::array<RationalPoint3, 3>& t) {
  std::vector<RationalPoint3> pts = poly;
  pts.insert(pts.end(), t.begin(), t.end());
  return pts;
}

// Strictly inside the triangle (relative interior), exact.
bool in_triangle_relative_interior(const RationalPoint3& q, const std::array<RationalPoint3, 3>& t) {
  if (orient3d(t[0], t[1], t[2], q) != Sign::Zero) return false;
  const Vec3<Exact> n = cross(t[1] - t[0], t[2] - t[0]);
  for (int i = 0; i < 3; ++i) {
    const auto& a = t[i];
    const auto& b = t[(i + 1) % 3];
    if (CGAL::sign(dot(cross(b - a, q - a), n)) != CGAL::POSITIVE) return false;
  }
  return true;
}

// Closed convex polygon membership, exact.
bool in_closed_polygon(const RationalPoint3& p, const Polygon3& poly) {
  const Plane3 pl = plane_of(poly);
  if (CGAL::sign(pl.value(p)) != CGAL::ZERO) return false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    if (CGAL::sign(dot(cross(b - a, p - a), pl.normal)) == CGAL::NEGATIVE) return false;
  }
  return true;
}

RationalPoint3 nearest_doubles(const RationalPoint3& p) {
  return {Exact(CGAL::to_double(p.x)), Exact(CGAL::to_double(p.y)), Exact(CGAL::to_double(p.z))};
}

}  // namespace

std::optional<Witness> round_witness(const Scene& scene, const CandidateFinder& candidates,
                                     const std::function<bool(const RationalPoint3&)>& on_source,
                                     std::int64_t triangle_index, const Witness& w) {
  const Witness r{nearest_doubles(w.p), nearest_doubles(w.q)};
  if (r.p == w.p && r.q == w.q) return w;
  const auto tri = triangle_points(scene, triangle_index);
  if (!on_source(r.p) || !in_triangle_relative_interior(r.q, tri)) return std::nullopt;
  const auto cands = candidates(enclosing_box({w.p, w.q, r.p, r.q}));
  if (!segment_is_free(scene, cands, r.p, r.q, triangle_index)) return std::nullopt;
  return r;
}

void accumulate(VisibilityStats& s, const VisibilityStats& f) {
  s.stabbing_pairs += f.stabbing_pairs;
  s.occluders_considered += f.occluders_considered;
  s.effective_occluders += f.effective_occluders;
  s.samples_cast += f.samples_cast;
  s.splits += f.splits;
  s.cones_created += f.cones_created;
  s.cones_alive_max = std::max(s.cones_alive_max, f.cones_alive_max);
  s.real_line_tests += f.real_line_tests;
  s.face_tests += f.face_tests;
  s.exact_evaluations += f.exact_evaluations;
  s.accepted_by_sampling |= f.accepted_by_sampling;
}

CandidateFinder brute_force_candidates(const Scene& scene) {
  return [&scene](const Box3& box) {
    std::vector<std::int64_t> out;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
      const auto& t = scene.triangles[i];
      bool overlap = true;
      for (int k = 0; k < 3 && overlap; ++k) {
        double lo = scene.corner(t, 0)[k], hi = lo;
        for (int c = 1; c < 3; ++c) {
          lo = std::min(lo, scene.corner(t, c)[k]);
          hi = std::max(hi, scene.corner(t, c)[k]);
        }
        overlap = hi >= box.lo[k] && lo <= box.hi[k];
      }
      if (overlap) out.push_back(static_cast<std::int64_t>(i));
    }
    return out;
  };
}

bool segment_is_free(const Scene& scene, const std::vector<std::int64_t>& candidates, const RationalPoint3& p,
                     const RationalPoint3& q, std::int64_t skip) {
  for (const std::int64_t idx : candidates) {
    if (idx == skip) continue;
    const auto t = triangle_points(scene, idx);
    if (open_segment_meets_closed_triangle(p, q, t[0], t[1], t[2])) return false;
  }
  return true;
}

void validate_source_polygon(const Polygon3& poly) {
  if (poly.size() < 3) throw std::invalid_argument("source polygon needs at least 3 vertices");
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (poly[i] == poly[(i + 1) % poly.size()]) throw std::invalid_argument("source polygon repeats a vertex");
  if (is_degenerate(poly)) throw std::invalid_argument("source polygon has zero area (collinear vertices)");
  const Plane3 pl = plane_of(poly);
  if (!lies_in_plane(poly, pl)) throw std::invalid_argument("source polygon is not planar");
  // Convex: every vertex turns the same way (w.r.t. the plane normal) and the loop winds once.
  int turn = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    const auto& c = poly[(i + 2) % poly.size()];
    const int s = CGAL::sign(dot(cross(b - a, c - b), pl.normal));
    if (s == 0) continue;
    if (turn != 0 && s != turn) throw std::invalid_argument("source polygon is not convex");
    turn = s;
  }
  // Winding once: every vertex must be on the inner side of every edge (closed), which rules out stars.
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    for (const auto& v : poly)
      if (CGAL::sign(dot(cross(b - a, v - a), pl.normal)) * turn < 0)
        throw std::invalid_argument("source polygon is not convex");
  }
}

VisibilityResult visible_from_polygon(const Scene& scene, const CandidateFinder& candidates, const Polygon3& source,
                                      std::int64_t triangle_index, const VisibilityOptions& options) {
  VisibilityResult result;
  result.triangle_index = triangle_index;
  const auto before = exact_evaluations_total();
  const auto tri = triangle_points(scene, triangle_index);
  const std::vector<std::int64_t> cands = candidates(enclosing_box(with_triangle(source, tri)));
  const std::vector<StabbingPair> pairs = stabbing_pairs(source, tri);
  result.stats.stabbing_pairs = static_cast<std::int64_t>(pairs.size());
  for (const auto& pair : pairs) {
    PairQuery query(scene, cands, triangle_index, pair, options, result.stats);
    if (auto w = query.run()) {
      result.visible = true;
      result.witness = w;
      if (options.round_witness)
        if (auto r = round_witness(scene, candidates, [&](const RationalPoint3& p) { return in_closed_polygon(p, source); },
                                   triangle_index, *w))
          result.witness = r;
      break;
    }
  }
  result.stats.exact_evaluations = static_cast<std::int64_t>(exact_evaluations_total() - before);
  return result;
}

namespace {

Polygon3 box_face(const Box3& b, int axis, bool high) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  auto pt = [&](double a, double bu, double bv) {
    Point3 p;
    p[axis] = a;
    p[u] = bu;
    p[v] = bv;
    return to_rational(p);
  };
  const double a = high ? b.hi[axis] : b.lo[axis];
  return {pt(a, b.lo[u], b.lo[v]), pt(a, b.hi[u], b.lo[v]), pt(a, b.hi[u], b.hi[v]), pt(a, b.lo[u], b.hi[v])};
}

bool in_closed_box(const RationalPoint3& p, const Box3& b) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < Exact(b.lo[k]) || p[k] > Exact(b.hi[k])) return false;
  return true;
}

// T meets the cell in a region of positive area: a short segment from inside the cell to a generic point
// of that region is free (docs/theory.md §5.5). Found by exact-checked sampling.
std::optional<Witness> witness_inside_cell(const Scene& scene, const std::vector<std::int64_t>& cands,
                                           const Polygon3& t_in, const std::array<RationalPoint3, 3>& tri,
                                           const Box3& cell, std::int64_t target, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x5bd1e995u);
  const Plane3 pl = plane_of({tri[0], tri[1], tri[2]});
  for (int attempt = 0; attempt < 64; ++attempt) {
    const RationalPoint3 q = random_interior_point(t_in, rng);
    for (int s : {+1, -1}) {
      Exact delta(1);
      for (int halving = 0; halving < 200; ++halving, delta = delta / 2) {
        const RationalPoint3 p = q + (Exact(s) * delta) * pl.normal;
        if (!in_closed_box(p, cell)) continue;
        if (segment_is_free(scene, cands, p, q, target)) return Witness{p, q};
      }
    }
  }
  return std::nullopt;
}

}  // namespace

VisibilityResult visible_from_box(const Scene& scene, const CandidateFinder& candidates, const Box3& cell,
                                  std::int64_t triangle_index, const VisibilityOptions& options) {
  for (int k = 0; k < 3; ++k)
    if (!(cell.lo[k] < cell.hi[k])) throw std::invalid_argument("view cell must have lo < hi in every coordinate");
  VisibilityResult result;
  result.triangle_index = triangle_index;
  const auto before = exact_evaluations_total();
  const auto tri = triangle_points(scene, triangle_index);

  // Part of T inside the closed cell.
  Polygon3 t_in{tri[0], tri[1], tri[2]};
  for (int axis = 0; axis < 3; ++axis)
    for (bool high : {false, true}) {
      Plane3 pl;
      pl.normal = {Exact(0), Exact(0), Exact(0)};
      pl.normal[axis] = high ? Exact(-1) : Exact(1);
      pl.offset = high ? Exact(-cell.hi[axis]) : Exact(cell.lo[axis]);
      t_in = clip_polygon(t_in, pl);
    }
  if (!is_degenerate(t_in)) {
    std::vector<RationalPoint3> pts{tri.begin(), tri.end()};
    pts.push_back(to_rational(cell.lo));
    pts.push_back(to_rational(cell.hi));
    const auto cands = candidates(enclosing_box(pts));
    if (auto w = witness_inside_cell(scene, cands, t_in, tri, cell, triangle_index, options.seed)) {
      result.visible = true;
      result.witness = w;
      if (options.round_witness)
        if (auto r = round_witness(scene, candidates, [&](const RationalPoint3& p) { return in_closed_box(p, cell); },
                                   triangle_index, *w))
          result.witness = r;
      result.stats.exact_evaluations = static_cast<std::int64_t>(exact_evaluations_total() - before);
      return result;
    }
    throw std::logic_error("from-region query: no witness found for a target inside the view cell");
  }

  // Otherwise every free segment leaves the cell through a face that T is (partly) in front of.
  for (int axis = 0; axis < 3 && !result.visible; ++axis)
    for (bool high : {false, true}) {
      const double plane = high ? cell.hi[axis] : cell.lo[axis];
      bool in_front = false;
      for (const auto& c : tri) in_front |= high ? (c[axis] > Exact(plane)) : (c[axis] < Exact(plane));
      if (!in_front) continue;
      VisibilityResult face = visible_from_polygon(scene, candidates, box_face(cell, axis, high), triangle_index, options);
      accumulate(result.stats, face.stats);
      if (face.visible) {
        result.visible = true;
        result.witness = face.witness;
        if (options.round_witness)
          if (auto r = round_witness(scene, candidates, [&](const RationalPoint3& p) { return in_closed_box(p, cell); },
                                     triangle_index, *face.witness))
            result.witness = r;
        break;
      }
    }
  result.stats.exact_evaluations = static_cast<std::int64_t>(exact_evaluations_total() - before);
  return result;
}

}  // namespace exactvis::region
