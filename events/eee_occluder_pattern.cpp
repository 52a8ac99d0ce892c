#include "events/eee_occluder_pattern.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"

#include <CGAL/FPU.h>

#include <algorithm>

namespace exactvis {
namespace {

using I = Interval;  // CGAL::Interval_nt<false>: only under the Protect_FPU_rounding of pattern()

constexpr int kUnknown = 2;  // a sign not certified (the others: -1, 0, +1)
constexpr int kPieces = 8;   // pieces of the range for the "no root on the range" test

struct Quad {
  I c[3];
  I operator()(const I& t) const { return c[0] + t * (c[1] + t * c[2]); }
  bool zero() const {  // certainly the zero polynomial (point enclosures of exact zeros)
    for (const I& x : c)
      if (!(x.inf() == 0 && x.sup() == 0)) return false;
    return true;
  }
};

int sign_of(const I& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  if (x.inf() == 0 && x.sup() == 0) return 0;
  return kUnknown;
}
bool nonzero(const I& x) { return x.inf() > 0 || x.sup() < 0; }
bool point_zero(const I& x) { return x.inf() == 0 && x.sup() == 0; }

// Three-valued logic of the sign function (false, true, not certified).
enum class Tri { False, True, Unknown };
Tri tri_and(Tri a, Tri b) {
  if (a == Tri::False || b == Tri::False) return Tri::False;
  if (a == Tri::True && b == Tri::True) return Tri::True;
  return Tri::Unknown;
}
// "some s > 0" (or "some s < 0" with want = -1) over certified-or-unknown signs.
Tri some(const int* s, int n, int want) {
  bool unknown = false;
  for (int i = 0; i < n; ++i) {
    if (s[i] == want) return Tri::True;
    unknown = unknown || s[i] == kUnknown;
  }
  return unknown ? Tri::Unknown : Tri::False;
}

// The polynomials of one occluder, in the order of `signs` below: q0, q1, q2, h0, h1, h2, den1, den2.
constexpr int kPolys = 8;
EeeOccluderPoly poly_kind(int i) {
  return i < 3 ? EeeOccluderPoly::Side : i < 6 ? EeeOccluderPoly::Height : EeeOccluderPoly::Den;
}
int poly_index(int i) { return i < 3 ? i : i < 6 ? i - 3 : i - 5; }

// The sign function of eee_event's exact analysis (blocked_in_gap): generator points strictly on both sides
// of the plane (heights of Q2, Q3 times the signs of den2, den3) and side signs not strictly mixed. Valid
// where L(t) is not in the occluder's plane and den2, den3 are nonzero (checked by the callers).
Tri sign_function(const int* s) {
  const int d1 = s[6], d2 = s[7];
  auto times = [](int a, int b) { return a == kUnknown || b == kUnknown ? kUnknown : a * b; };
  const int hs[3] = {s[3], times(s[4], d1), times(s[5], d2)};
  const Tri crosses = tri_and(some(hs, 3, 1), some(hs, 3, -1));
  const Tri mixed = tri_and(some(s, 3, 1), some(s, 3, -1));
  const Tri not_mixed = mixed == Tri::True ? Tri::False : mixed == Tri::False ? Tri::True : Tri::Unknown;
  return tri_and(crosses, not_mixed);
}

struct RootEnclosure {
  double lo, hi;
  int poly;
};

// Certifies p != 0 on [lo, hi] (8 pieces, Horner's rule over each).
bool no_root_on(const Quad& p, double lo, double hi) {
  const I l(lo), width = I(hi) - l;
  I prev = l;
  for (int i = 1; i <= kPieces; ++i) {
    const I next = i == kPieces ? I(hi) : l + width * I(double(i) / kPieces);
    if (!nonzero(p(I(prev.inf(), next.sup())))) return false;
    prev = next;
  }
  return true;
}

// Appends enclosures of the roots of p strictly inside (vmin, vmax); false when that set is not certified
// (a root whose enclosure meets the enclosure of vmin or vmax, a possibly double root, a leading
// coefficient that may vanish). The zero polynomial has no roots (as real_roots says).
bool inner_roots(const Quad& p, int poly, const I& vmin, const I& vmax, std::vector<RootEnclosure>& out,
                 bool& verify) {
  auto place = [&](const I& r) {
    if (r.sup() < vmin.inf() || r.inf() > vmax.sup()) return true;  // outside [vmin, vmax]
    // A point enclosure is the exact root: equal to an exact end (a point too), it is not inside.
    const bool point = r.inf() == r.sup();
    if (point && ((vmin.inf() == vmin.sup() && r.inf() == vmin.inf()) || (vmax.inf() == vmax.sup() && r.inf() == vmax.inf())))
      return true;
    if (r.inf() > vmin.sup() && r.sup() < vmax.inf()) {
      out.push_back({r.inf(), r.sup(), poly});
      return true;
    }
    // Meets exactly one end's enclosure: assumed not inside (a tie with that end), checked by the caller.
    const bool near_lo = r.inf() <= vmin.sup(), near_hi = r.sup() >= vmax.inf();
    if (near_lo != near_hi) {
      verify = true;
      return true;
    }
    return false;
  };
  const I &a = p.c[2], &b = p.c[1], &c = p.c[0];
  if (nonzero(a)) {
    const I disc = b * b - I(4) * a * c;
    if (disc.sup() < 0) return true;  // no real root
    if (disc.inf() > 0) {
      const I s = CGAL::sqrt(disc);
      if (b.inf() > 0 || b.sup() < 0) {  // no cancellation: q = -(b + sign(b) s) / 2, roots q / a and c / q
        const I q = b.inf() > 0 ? -(b + s) / I(2) : (s - b) / I(2);
        return place(q / a) && place(c / q);
      }
      return place((-b - s) / (I(2) * a)) && place((-b + s) / (I(2) * a));
    }
    return no_root_on(p, vmin.inf(), vmax.sup());
  }
  if (point_zero(a)) {
    if (nonzero(b)) return place(-c / b);
    if (point_zero(b)) return true;  // a constant has no roots (the zero polynomial neither, as in real_roots)
  }
  return no_root_on(p, vmin.inf(), vmax.sup());
}

}  // namespace

bool EeeOccluderPattern::blocks_nothing() const {
  for (char g : gap_blocked)
    if (g) return false;
  for (const auto& b : inner)
    if (b.blocked) return false;
  return true;
}

EeeOccluderPatternFilter::EeeOccluderPatternFilter(const VecPoly& p, const VecPoly& num1, const ScalarPoly& den1,
                                                   const VecPoly& num2, const ScalarPoly& den2, const VecPoly& ld,
                                                   const VecPoly& lm) {
  auto put = [](IPoly& out, const ScalarPoly& in) {
    for (int j = 0; j < 3; ++j) {
      const auto e = tight_interval(in[j]);
      out[j] = {e.first, e.second};
    }
  };
  for (int k = 0; k < 3; ++k) {
    put(p_[k], p[k]);
    put(num_[0][k], num1[k]);
    put(num_[1][k], num2[k]);
    put(ld_[k], ld[k]);
    put(lm_[k], lm[k]);
  }
  put(den_[0], den1);
  put(den_[1], den2);
}

std::optional<EeeOccluderPattern> EeeOccluderPatternFilter::pattern(const Point3& a, const Point3& b,
                                                                    const Point3& c,
                                                                    const std::pair<double, double>& vmin_e,
                                                                    const std::pair<double, double>& vmax_e) const {
  static PredicateCounter counter("eee_occluder_pattern");
  std::atomic<std::uint64_t>* counts = counter.thread_counts();
  detail::bump(counts[0]);
  auto not_certified = [&]() -> std::optional<EeeOccluderPattern> {
    detail::bump(counts[1 + static_cast<int>(FilterLayer::Exact)]);
    return std::nullopt;
  };
  if (!filter_enabled()) return not_certified();
  std::optional<EeeOccluderPattern> result;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const I vmin(vmin_e.first, vmin_e.second), vmax(vmax_e.first, vmax_e.second);
    auto ip = [](const Enclosure& e) { return I(e[0], e[1]); };
    // The occluder's plane n.x = k and edge lines e_j = (c_j+1 - c_j, c_j x c_j+1), in intervals.
    const I v[3][3] = {{I(a.x), I(a.y), I(a.z)}, {I(b.x), I(b.y), I(b.z)}, {I(c.x), I(c.y), I(c.z)}};
    I u[3], w[3], n[3];
    for (int j = 0; j < 3; ++j) u[j] = v[1][j] - v[0][j], w[j] = v[2][j] - v[0][j];
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    const I k = n[0] * v[0][0] + n[1] * v[0][1] + n[2] * v[0][2];
    Quad poly[kPolys];
    for (int e = 0; e < 3; ++e) {  // q_e = d(t) . m_e + m(t) . d_e
      const I* p = v[e];
      const I* r = v[(e + 1) % 3];
      const I ed[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      const I em[3] = {p[1] * r[2] - p[2] * r[1], p[2] * r[0] - p[0] * r[2], p[0] * r[1] - p[1] * r[0]};
      for (int j = 0; j < 3; ++j) {
        I s(0);
        for (int x = 0; x < 3; ++x) s += ip(ld_[x][j]) * em[x] + ip(lm_[x][j]) * ed[x];
        poly[e].c[j] = s;
      }
    }
    for (int j = 0; j < 3; ++j) {  // heights: n . P - k, n . num_q - k den_q
      I h0 = -(j == 0 ? k : I(0)), h1 = -k * ip(den_[0][j]), h2 = -k * ip(den_[1][j]);
      for (int x = 0; x < 3; ++x) {
        h0 += n[x] * ip(p_[x][j]);
        h1 += n[x] * ip(num_[0][x][j]);
        h2 += n[x] * ip(num_[1][x][j]);
      }
      poly[3].c[j] = h0;
      poly[4].c[j] = h1;
      poly[5].c[j] = h2;
      poly[6].c[j] = ip(den_[0][j]);
      poly[7].c[j] = ip(den_[1][j]);
    }
    bool identically_zero[kPolys];
    bool verify[kPolys] = {};
    std::vector<RootEnclosure> roots;
    bool ok = vmin.sup() < vmax.inf();
    for (int i = 0; ok && i < kPolys; ++i) {
      identically_zero[i] = poly[i].zero();
      ok = inner_roots(poly[i], i, vmin, vmax, roots, verify[i]);
    }

    if (ok) {
      std::sort(roots.begin(), roots.end(), [](const RootEnclosure& x, const RootEnclosure& y) { return x.lo < y.lo; });
      for (std::size_t i = 0; ok && i + 1 < roots.size(); ++i) ok = roots[i].hi < roots[i + 1].lo;
    }
    EeeOccluderPattern pat;
    const std::size_t nb = roots.size();
    // Signs of the polynomials at a double sample strictly inside each gap (nonzero there unless identically 0).
    std::vector<std::array<int, kPolys>> gap_signs;
    if (ok) {
      gap_signs.resize(nb + 1);
      pat.gap_blocked.resize(nb + 1);
      for (std::size_t g = 0; ok && g <= nb; ++g) {
        const double lo = g == 0 ? vmin.sup() : roots[g - 1].hi, hi = g == nb ? vmax.inf() : roots[g].lo;
        const double s = lo + (hi - lo) / 2;  // rounded upward; checked
        if (!(lo < s && s < hi)) {
          ok = false;
          break;
        }
        const I t(s);
        for (int i = 0; i < kPolys; ++i) gap_signs[g][i] = identically_zero[i] ? 0 : sign_of(poly[i](t));
        const int* sg = gap_signs[g].data();
        const Tri st = sg[6] == 0 || sg[7] == 0 ? Tri::Unknown : sign_function(sg);
        if (st == Tri::Unknown) ok = false;
        pat.gap_blocked[g] = st == Tri::True;
      }
    }
    if (ok) {
      int rank[kPolys] = {};
      pat.inner.resize(nb);
      for (std::size_t i = 0; ok && i < nb; ++i) {
        EeeOccluderBreakpoint& bp = pat.inner[i];
        const int own = roots[i].poly;
        bp.poly = poly_kind(own);
        bp.index = poly_index(own);
        bp.rank = rank[own]++;
        if (bp.poly == EeeOccluderPoly::Den) continue;  // L(t) parallel to E_k's line: never blocked (exact test)
        // The other polynomials have no root between the samples of the gaps on both sides: their signs there.
        std::array<int, kPolys> s = gap_signs[i];
        s[own] = 0;
        const int zero_heights = (s[3] == 0) + (s[4] == 0) + (s[5] == 0);
        if (zero_heights >= 2 || s[6] == 0 || s[7] == 0) {  // L(t) in the occluder's plane (or degenerate)
          ok = false;
          break;
        }
        const Tri st = sign_function(s.data());
        if (st == Tri::Unknown) ok = false;
        bp.blocked = st == Tri::True;
      }
    }
    for (int i = 0; ok && i < kPolys; ++i)
      if (verify[i]) pat.verify.push_back({poly_kind(i), poly_index(i), 0, false});
    if (ok) result = std::move(pat);
  }
  if (!result) return not_certified();
  detail::bump(counts[1 + static_cast<int>(FilterLayer::Interval)]);
  return result;
}

}  // namespace exactvis
