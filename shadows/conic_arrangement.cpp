// CGAL's preconditions stay on in this file (also in release builds): CGAL 5.5's conic traits can violate
// them on valid input (see the header), and a violated precondition is then an exception we catch instead
// of a crash further on.
#undef NDEBUG
#include "shadows/conic_arrangement.hpp"

#include "shadows/arrangement_face_id.hpp"
#include "shadows/polyline_arrangement.hpp"

#include <CGAL/Arr_batched_point_location.h>
#include <CGAL/Arr_conic_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/CORE_algebraic_number_traits.h>
#include <CGAL/Cartesian.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>

namespace exactvis::shadows {
namespace {

using NtTraits = CGAL::CORE_algebraic_number_traits;
using Rational = NtTraits::Rational;    // CORE::BigRat
using Algebraic = NtTraits::Algebraic;  // CORE::Expr
using RatKernel = CGAL::Cartesian<Rational>;
using AlgKernel = CGAL::Cartesian<Algebraic>;
using Traits = CGAL::Arr_conic_traits_2<RatKernel, AlgKernel, NtTraits>;
using Point = Traits::Point_2;
using Curve = Traits::Curve_2;
using XCurve = Traits::X_monotone_curve_2;
using Dcel = CGAL::Arr_face_extended_dcel<Traits, int>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;

Rational to_rational(const Exact& x) { return Rational(x.mpq()); }
Exact from_rational(const Rational& q) { return Exact(q.get_mp()); }
Algebraic to_algebraic(const Exact& x) { return Algebraic(to_rational(x)); }
RatKernel::Point_2 rat_point(const std::array<Exact, 2>& p) { return {to_rational(p[0]), to_rational(p[1])}; }
Point alg_point(const std::array<Exact, 2>& p) { return {to_algebraic(p[0]), to_algebraic(p[1])}; }

int orient(const std::array<Exact, 2>& a, const std::array<Exact, 2>& b, const std::array<Exact, 2>& c) {
  return CGAL::sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

// A rational strictly between algebraic a < b: first the midpoint of double approximations, then midpoints
// of ever finer CORE approximations (exact comparisons decide).
Rational rational_between(const Algebraic& a, const Algebraic& b) {
  {
    const double m = 0.5 * (CGAL::to_double(a) + CGAL::to_double(b));
    if (std::isfinite(m)) {
      const Rational q(m);
      const Algebraic qa(q);
      if (a < qa && qa < b) return q;
    }
  }
  for (long bits = 64; bits <= (1L << 16); bits *= 2) {
    const Rational qa = a.approx(CORE::extLong::getPosInfty(), bits).BigRatValue();
    const Rational qb = b.approx(CORE::extLong::getPosInfty(), bits).BigRatValue();
    const Rational q = (qa + qb) / Rational(2);
    const Algebraic x(q);
    if (a < x && x < b) return q;
  }
  throw std::runtime_error("receiver_arrangement: two algebraic numbers closer than 2^-65536");
}

void add_polyline(const ArrangementCurve& c, std::vector<Curve>& out) {
  for (std::size_t k = 0; k + 1 < c.points.size(); ++k)
    if (c.points[k] != c.points[k + 1])
      out.emplace_back(RatKernel::Segment_2(rat_point(c.points[k]), rat_point(c.points[k + 1])));
}

// The conic arc through the curve's points, or nothing when the conic is degenerate or an interior point is
// not on the constructed arc.
std::optional<Curve> conic_arc(const ArrangementCurve& c) {
  const auto& q = *c.conic;  // u^2, uv, v^2, u, v, 1
  const Exact& r = q[0];
  const Exact& t = q[1];
  const Exact& s = q[2];
  const Exact& u = q[3];
  const Exact& v = q[4];
  const Exact& w = q[5];
  // Degenerate iff det [[2r, t, u], [t, 2s, v], [u, v, 2w]] = 0 (includes the line case r = s = t = 0).
  const Exact det = 2 * r * (4 * s * w - v * v) - t * (2 * t * w - u * v) + u * (t * v - 2 * s * u);
  if (det == 0 || c.points.size() < 3) return std::nullopt;
  const auto& p0 = c.points.front();
  const auto& p1 = c.points.back();
  if (p0 == p1) return std::nullopt;
  const int turn = orient(p0, c.points[c.points.size() / 2], p1);
  if (turn == 0) return std::nullopt;
  for (const auto& p : c.points)  // the points must lie on the conic
    if (r * p[0] * p[0] + t * p[0] * p[1] + s * p[1] * p[1] + u * p[0] + v * p[1] + w != 0) return std::nullopt;
  Curve arc(to_rational(r), to_rational(s), to_rational(t), to_rational(u), to_rational(v), to_rational(w),
            turn > 0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE, alg_point(p0), alg_point(p1));
  if (!arc.is_valid()) return std::nullopt;
  std::vector<XCurve> pieces;
  Traits traits;
  std::vector<boost::variant<Point, XCurve>> parts;
  traits.make_x_monotone_2_object()(arc, std::back_inserter(parts));
  for (const auto& part : parts)
    if (const XCurve* x = boost::get<XCurve>(&part)) pieces.push_back(*x);
  for (std::size_t k = 1; k + 1 < c.points.size(); ++k) {
    const Point p = alg_point(c.points[k]);
    bool on = false;
    for (const auto& x : pieces)
      if (x.contains_point(p)) {
        on = true;
        break;
      }
    if (!on) return std::nullopt;
  }
  return arc;
}

bool is_conic(const XCurve& x) { return CGAL::sign(x.r()) != 0 || CGAL::sign(x.s()) != 0 || CGAL::sign(x.t()) != 0; }

// Points of an x-monotone arc in doubles, left to right, at x = xl + (xr - xl) (1 - cos(pi k / n)) / 2: the
// cosine grading makes the arc smooth in k even at vertical tangents (always at the ends of x-monotone
// arcs, where y - y_end ~ sqrt(x - x_end)), so the chord polygon's area error is O(n^-2) with an even
// expansion (Richardson applies). y(x) is the root of s y^2 + (t x + v) y + (r x^2 + u x + w) = 0 on the
// arc's branch, chosen once against the exact point at the middle abscissa.
std::vector<std::pair<double, double>> arc_points(const XCurve& cv, int n) {
  const double xl = CGAL::to_double(cv.left().x()), yl = CGAL::to_double(cv.left().y());
  const double xr = CGAL::to_double(cv.right().x()), yr = CGAL::to_double(cv.right().y());
  if (!is_conic(cv)) return {{xl, yl}, {xr, yr}};
  const double r = CGAL::to_double(cv.r()), s = CGAL::to_double(cv.s()), t = CGAL::to_double(cv.t());
  const double u = CGAL::to_double(cv.u()), v = CGAL::to_double(cv.v()), w = CGAL::to_double(cv.w());
  const bool linear = CGAL::sign(cv.s()) == 0;
  auto root = [&](double x, int branch) {
    const double B = t * x + v, C = (r * x + u) * x + w;
    if (linear) return -C / B;
    const double sq = std::sqrt(std::max(0.0, B * B - 4 * s * C));
    return branch > 0 ? (-B + sq) / (2 * s) : (-B - sq) / (2 * s);
  };
  int branch = 1;
  if (!linear) {
    const Algebraic xm = (cv.left().x() + cv.right().x()) / 2;
    const double ym = CGAL::to_double(cv.point_at_x(Point(xm, Algebraic(0))).y()), dxm = CGAL::to_double(xm);
    branch = std::abs(root(dxm, 1) - ym) <= std::abs(root(dxm, -1) - ym) ? 1 : -1;
  }
  const double pi = std::acos(-1.0);
  std::vector<std::pair<double, double>> pts{{xl, yl}};
  for (int k = 1; k < n; ++k) {
    const double x = xl + (xr - xl) * (1 - std::cos(pi * k / n)) / 2;
    pts.emplace_back(x, root(x, branch));
  }
  pts.emplace_back(xr, yr);
  return pts;
}

// Signed integral of (x dy - y dx) / 2 along the halfedge's curve in its direction, from an n-piece polyline.
double halfedge_area(const Arrangement::Halfedge_const_handle& h, int n) {
  std::vector<std::pair<double, double>> pts = arc_points(h->curve(), n);
  if (h->direction() == CGAL::ARR_RIGHT_TO_LEFT) std::reverse(pts.begin(), pts.end());
  double a = 0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k)
    a += pts[k].first * pts[k + 1].second - pts[k + 1].first * pts[k].second;
  return 0.5 * a;
}


}  // namespace

namespace {

using Lens = std::array<std::array<Exact, 2>, 3>;

// The triangle (a, b, c), c where the conic's tangents at a and b meet: it holds the conic's arc from a to b
// when that arc turns by less than a half turn, which holds iff c lies on the side of the chord the arc
// bulges to (right of a -> b for a left-turning arc). Exact; none when that fails.
std::optional<Lens> lens_triangle(const std::array<Exact, 6>& q, const std::array<Exact, 2>& a,
                                  const std::array<Exact, 2>& b, int turn) {
  auto grad = [&](const std::array<Exact, 2>& p) {
    return std::array<Exact, 2>{2 * q[0] * p[0] + q[1] * p[1] + q[3], q[1] * p[0] + 2 * q[2] * p[1] + q[4]};
  };
  const auto ga = grad(a), gb = grad(b);
  // ga . X = ga . a, gb . X = gb . b
  const Exact det = ga[0] * gb[1] - ga[1] * gb[0];
  if (det == 0) return std::nullopt;
  const Exact ra = ga[0] * a[0] + ga[1] * a[1], rb = gb[0] * b[0] + gb[1] * b[1];
  const std::array<Exact, 2> c{(ra * gb[1] - ga[1] * rb) / det, (ga[0] * rb - ra * gb[0]) / det};
  if (orient(a, b, c) != -turn) return std::nullopt;
  return Lens{a, b, c};
}

bool in_closed_triangle(const std::array<Exact, 2>& p, const Lens& t) {
  const int o0 = orient(t[0], t[1], p), o1 = orient(t[1], t[2], p), o2 = orient(t[2], t[0], p);
  return (o0 >= 0 && o1 >= 0 && o2 >= 0) || (o0 <= 0 && o1 <= 0 && o2 <= 0);
}


// The face of each query: one batched sweep over the edges and all queries (CGAL::locate, O((E + Q) log E)),
// matched back to the queries by sorting them in the sweep's xy-lexicographic order (each match checked
// exactly). If the sweep throws (CGAL 5.5's conic traits violate their preconditions on some arrangements,
// see the header), a match fails or a query lands in a face without an id, that query takes the naive
// location (every edge, O(E)). No walk along a line: on the arrangements where the sweep throws, CGAL
// 5.5's walk can go round a cycle of faces for ever with these traits (seen at room 3000: one query of a
// 45-query receiver walking for minutes; the runs at 5000 and 10^4 never ended, docs/performance.md).
std::vector<int> locate_queries(const Arrangement& arr, const std::vector<std::array<Exact, 2>>& queries) {
  std::vector<int> faces(queries.size(), -1);
  std::vector<char> done(queries.size(), 0);
  if (!queries.empty()) {
    std::vector<std::size_t> order(queries.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return queries[a] < queries[b]; });
    std::vector<Point> pts;
    pts.reserve(order.size());
    for (std::size_t k : order) pts.push_back(alg_point(queries[k]));
    using Result = std::pair<Point, CGAL::Arr_point_location_result<Arrangement>::Type>;
    std::vector<Result> results;
    try {
      CGAL::locate(arr, pts.begin(), pts.end(), std::back_inserter(results));
    } catch (const CGAL::Failure_exception&) {
      results.clear();
    }
    if (results.size() == pts.size()) {
      for (std::size_t k = 0; k < results.size(); ++k) {
        const Point& p = results[k].first;
        // The sweep hands back copies sharing the query's representation (same address: no CORE
        // comparison); otherwise (a query on an arrangement vertex) compare exactly.
        const bool same = (&p.x() == &pts[k].x() && &p.y() == &pts[k].y()) ||
                          (p.x() == pts[k].x() && p.y() == pts[k].y());
        if (!same) break;  // not the expected order: the rest take the naive location
        const int id = arrangement_face_id<Arrangement>(results[k].second);
        if (id >= 0 || boost::get<Arrangement::Face_const_handle>(&results[k].second) == nullptr) {
          faces[order[k]] = id;
          done[order[k]] = 1;
        }
      }
    }
  }
  std::optional<CGAL::Arr_naive_point_location<Arrangement>> naive;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    if (done[k]) continue;
    if (!naive) naive.emplace(arr);
    faces[k] = arrangement_face_id<Arrangement>(naive->locate(alg_point(queries[k])));
  }
  return faces;
}

ReceiverArrangement build(const std::vector<ArrangementCurve>& curves, const std::vector<std::array<Exact, 2>>& queries,
                          bool trim, bool incremental) {
  ReceiverArrangement out;
  std::vector<Lens> lenses;
  std::vector<Curve> input;
  const std::array<std::array<Exact, 2>, 3> corner{{{Exact(0), Exact(0)}, {Exact(1), Exact(0)}, {Exact(0), Exact(1)}}};
  for (int k = 0; k < 3; ++k)
    input.emplace_back(RatKernel::Segment_2(rat_point(corner[k]), rat_point(corner[(k + 1) % 3])));
  for (const auto& c : curves) {
    if (c.conic && trim) {
      // The arc without its first and last pieces, which enter as chords with their lens triangles.
      const std::size_t n = c.points.size();
      if (n >= 4) {
        ArrangementCurve inner;
        inner.points.assign(c.points.begin() + 1, c.points.end() - 1);
        inner.conic = c.conic;
        if (auto arc = conic_arc(inner)) {
          const int turn = orient(inner.points.front(), inner.points[inner.points.size() / 2], inner.points.back());
          input.push_back(std::move(*arc));
          ++out.conic_arcs;
          ++out.trimmed_arcs;
          for (const auto& [a, b] : {std::pair{c.points[0], c.points[1]}, std::pair{c.points[n - 2], c.points[n - 1]}}) {
            if (a == b) continue;
            input.emplace_back(RatKernel::Segment_2(rat_point(a), rat_point(b)));
            if (auto l = lens_triangle(*c.conic, a, b, turn)) lenses.push_back(*l);
            else ++out.uncertified_lenses;
          }
          continue;
        }
      }
      ++out.chord_curves;
    } else if (c.conic) {
      if (auto arc = conic_arc(c)) {
        input.push_back(std::move(*arc));
        ++out.conic_arcs;
        continue;
      }
      ++out.chord_curves;
    }
    add_polyline(c, input);
  }
  Arrangement arr;
  if (incremental) {
    // Zone walks instead of one sweep, each curve's first point found by the naive location: CGAL's default
    // (the walk along a line) was seen not returning on these arrangements at room 10^4 (see locate_queries).
    const CGAL::Arr_naive_point_location<Arrangement> naive(arr);
    for (const auto& cv : input) CGAL::insert(arr, cv, naive);
  } else {
    CGAL::insert(arr, input.begin(), input.end());
  }
  out.vertices = arr.number_of_vertices();
  out.edges = arr.number_of_edges();

  // Vertex x-coordinates, sorted and unique (samples avoid them).
  std::vector<Algebraic> vx;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) vx.push_back(v->point().x());
  std::sort(vx.begin(), vx.end());
  vx.erase(std::unique(vx.begin(), vx.end()), vx.end());
  struct EdgeBox {
    Arrangement::Halfedge_const_handle h;
    double xmin, xmax;
  };
  std::vector<EdgeBox> edges;  // non-vertical edges with their double x-range (widened)
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    if (e->curve().is_vertical()) continue;
    const double a = CGAL::to_double(e->curve().left().x()), b = CGAL::to_double(e->curve().right().x());
    edges.push_back({e, a - 1e-9 - 1e-9 * std::abs(a), b + 1e-9 + 1e-9 * std::abs(b)});
  }

  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    f->set_data(-1);
    if (f->is_unbounded()) continue;
    ReceiverArrangement::Face face;
    // Area and conic flag over every boundary cycle (the face is on each halfedge's left).
    double a1 = 0, a2 = 0;
    auto add_ccb = [&](Arrangement::Ccb_halfedge_const_circulator c0) {
      auto c = c0;
      do {
        if (is_conic(c->curve())) face.conic_bounded = true;
        a1 += halfedge_area(c, 32);
        a2 += halfedge_area(c, 64);
      } while (++c != c0);
    };
    add_ccb(f->outer_ccb());
    for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic) add_ccb(*ic);
    face.area_uv = face.conic_bounded ? a2 + (a2 - a1) / 3 : a2;
    // Sample: on an outer-boundary edge, probe vertically towards the face.
    bool found = false, certified = false;
    auto c0 = f->outer_ccb();
    auto c = c0;
    do {
      if (c->curve().is_vertical()) continue;
      const Arrangement::Halfedge_const_handle hc = c;
      const XCurve& cv = hc->curve();
      const Algebraic& xl = cv.left().x();
      const Algebraic& xr = cv.right().x();
      const auto next = std::upper_bound(vx.begin(), vx.end(), xl);
      const Algebraic& xhi = (next != vx.end() && *next < xr) ? *next : xr;
      const Rational x0 = rational_between(xl, xhi);
      const Algebraic ax0(x0);
      const Algebraic yc = cv.point_at_x(Point(ax0, Algebraic(0))).y();
      const bool above = hc->direction() == CGAL::ARR_LEFT_TO_RIGHT;  // the face lies above the edge
      const double dx0 = CGAL::to_double(x0);
      std::optional<Algebraic> ybound;
      for (const auto& e : edges) {
        if (e.h == hc || e.h == hc->twin() || dx0 < e.xmin || dx0 > e.xmax) continue;
        const XCurve& ecv = e.h->curve();
        if (!(ecv.left().x() < ax0 && ax0 < ecv.right().x())) continue;
        const Algebraic y = ecv.point_at_x(Point(ax0, Algebraic(0))).y();
        if (above ? (y > yc && (!ybound || y < *ybound)) : (y < yc && (!ybound || y > *ybound))) ybound = y;
      }
      if (!ybound) continue;  // cannot happen for a bounded face; try another edge
      const Rational y0 = above ? rational_between(yc, *ybound) : rational_between(*ybound, yc);
      const std::array<Exact, 2> cand{from_rational(x0), from_rational(y0)};
      if (!found) face.sample = cand;
      found = true;
      // Outside every chord's lens triangle the sample is on the same side of the true arc as of the chord.
      if (std::none_of(lenses.begin(), lenses.end(), [&](const Lens& l) { return in_closed_triangle(cand, l); })) {
        face.sample = cand;
        certified = true;
        break;
      }
    } while (++c != c0);
    if (!found) throw std::logic_error("receiver_arrangement: no sample found for a bounded face");
    if (!certified) ++out.uncertified_samples;
    // A bounded face outside the unit triangle (an arc leaving it between its points) is not reported.
    const auto& q = face.sample;
    if (!(q[0] > 0 && q[1] > 0 && q[0] + q[1] < 1)) continue;
    f->set_data(static_cast<int>(out.faces.size()));
    out.faces.push_back(std::move(face));
  }

  out.query_faces = locate_queries(arr, queries);
  return out;
}

}  // namespace

void dump_arrangement_curves(const std::vector<ArrangementCurve>& curves, const std::string& why) {
  static std::atomic<int> counter{0};
  const char* dir = std::getenv("EXACTVIS_DUMP_ARRANGEMENTS");
  if (dir == nullptr || *dir == 0) return;
  std::ofstream f(std::string(dir) + "/arrangement_" + std::to_string(counter++) + ".txt");
  std::string one_line = why;
  std::replace(one_line.begin(), one_line.end(), '\n', ' ');
  f << "# " << one_line << "\n";
  for (const auto& c : curves) {
    f << "curve " << c.points.size() << " " << (c.conic ? 1 : 0) << "\n";
    if (c.conic)
      for (int k = 0; k < 6; ++k) f << to_rational_string((*c.conic)[k]) << (k < 5 ? " " : "\n");
    for (const auto& p : c.points) f << to_rational_string(p[0]) << " " << to_rational_string(p[1]) << "\n";
  }
}

ReceiverArrangement receiver_arrangement(const std::vector<ArrangementCurve>& curves,
                                         const std::vector<std::array<Exact, 2>>& queries) {
  // Aggregated sweep, then incremental insertion on the arcs as given; then the certified polyline
  // arrangement (exact faces, shadows/polyline_arrangement.hpp); then sweep and incremental insertion with
  // trimmed arcs.
  std::string first;
  for (const bool incremental : {false, true}) {
    try {
      return build(curves, queries, false, incremental);
    } catch (const CGAL::Failure_exception& e) {
      if (first.empty()) first = e.what();
    }
  }
  ReceiverArrangement poly = polyline_arrangement(curves, queries);
  dump_arrangement_curves(curves, first + (poly.failed ? "; " + poly.failure : "; polyline certified"));
  if (!poly.failed) return poly;
  for (const bool incremental : {false, true}) {
    try {
      return build(curves, queries, true, incremental);
    } catch (const CGAL::Failure_exception&) {
    }
  }
  ReceiverArrangement out;
  out.failed = true;
  out.failure = first + "; " + poly.failure;
  return out;
}

}  // namespace exactvis::shadows
