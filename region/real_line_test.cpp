#include "region/real_line_test.hpp"

#include <boost/dynamic_bitset.hpp>

#include <deque>
#include <set>
#include <stdexcept>

namespace exactvis::region {
namespace {

IntVec6 combine(const mpz_class& a, const IntVec6& x, const mpz_class& b, const IntVec6& y) {
  IntVec6 v;
  for (int k = 0; k < 6; ++k) v[k] = a * x[k] + b * y[k];
  normalize(v);
  return v;
}

IntVec6 negated(IntVec6 v) {
  for (auto& c : v) c = -c;
  return v;
}

// Indices of a maximal linearly independent subset of `vs` (exact elimination).
std::vector<std::size_t> independent_subset(const std::vector<const IntVec6*>& vs) {
  std::vector<RatVec6> basis;  // reduced rows
  std::vector<int> pivots;
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < vs.size() && chosen.size() < 6; ++i) {
    RatVec6 v;
    for (int k = 0; k < 6; ++k) v[k] = (*vs[i])[k];
    for (std::size_t b = 0; b < basis.size(); ++b) {
      const int p = pivots[b];
      if (sgn(v[p]) == 0) continue;
      const mpq_class f = v[p] / basis[b][p];
      for (int k = 0; k < 6; ++k) v[k] -= f * basis[b][k];
    }
    int p = -1;
    for (int k = 0; k < 6; ++k)
      if (sgn(v[k]) != 0) {
        p = k;
        break;
      }
    if (p < 0) continue;
    basis.push_back(v);
    pivots.push_back(p);
    chosen.push_back(i);
  }
  return chosen;
}

// Solve M y = rhs (n x n, exact). Returns false when M is singular.
bool solve(std::vector<std::vector<mpq_class>> m, std::vector<mpq_class> rhs, std::vector<mpq_class>& y) {
  const std::size_t n = rhs.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    while (p < n && sgn(m[p][c]) == 0) ++p;
    if (p == n) return false;
    std::swap(m[p], m[c]);
    std::swap(rhs[p], rhs[c]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c || sgn(m[r][c]) == 0) continue;
      const mpq_class f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < n; ++k) m[r][k] -= f * m[c][k];
      rhs[r] -= f * rhs[c];
    }
  }
  y.resize(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = rhs[i] / m[i][i];
  return true;
}

struct SignSearch {
  bool have_pos = false, have_neg = false;
  ConeVector6 pos{}, neg{};
  bool done() const { return have_pos && have_neg; }
  void offer(const IntVec6& x) {
    if (done()) return;
    take(plucker_form_sign(x, approximate(x)), [&] { return ConeVector6(x); });
  }
  void offer(const ConeVector6& x) {
    if (done()) return;
    take(plucker_form_sign(x), [&] { return x; });
  }
  template <class Value>
  void take(int s, Value&& value) {
    if (s > 0 && !have_pos) {
      have_pos = true;
      pos = value();
    } else if (s < 0 && !have_neg) {
      have_neg = true;
      neg = value();
    }
  }
};

// A point a*ri + b*rj (a, b >= 0) where q has sign `want` (+1/-1), if the 2D cone has one.
// The signs are layered first (filter, fixed, gmp); GMP values only for a combination.
std::optional<ConeVector6> pair_point(const ConeVector6& rci, const ConeVector6& rcj, int want) {
  // want*q(a ri + b rj) = a^2 qi + a b s + b^2 qj ; look for a value > 0.
  const int sqi = want * plucker_form_sign(rci);
  if (sqi > 0) return rci;
  const int sqj = want * plucker_form_sign(rcj);
  if (sqj > 0) return rcj;
  if (want * side_sign(rci, rcj) <= 0) return std::nullopt;
  const IntVec6 ri = rci.to_gmp(), rj = rcj.to_gmp();
  const mpz_class qi = want * plucker_form(ri), qj = want * plucker_form(rj), s = want * side6(ri, rj);
  if (sgn(qi) == 0) {  // a = 1, b large: b s + b^2 qj > 0 for b = 1 + floor(-qj... ) pick b with b (s + b qj) > 0
    if (sgn(qj) == 0) return ConeVector6(combine(1, ri, 1, rj));
    // qj < 0: b = s / (2 |qj|) makes s + b qj = s/2 > 0
    return ConeVector6(combine(2 * (-qj), ri, s, rj));
  }
  if (sgn(qj) == 0) return ConeVector6(combine(s, ri, 2 * (-qi), rj));
  // qi, qj < 0: positive values exist iff s^2 > 4 qi qj; then at a = s, b = -2 qi: a^2 qi + ab s + b^2 qj =
  // s^2 qi - 2 qi s^2 + 4 qi^2 qj = -qi (s^2 - 4 qi qj) > 0.
  if (s * s > 4 * qi * qj) return ConeVector6(combine(s, ri, -2 * qi, rj));
  return std::nullopt;
}

}  // namespace

RealLineTest test_real_lines(const PolyhedralCone6& cone) {
  RealLineTest out;
  SignSearch search;
  auto finish = [&](int step) {
    out.has_real_lines = search.done();
    out.positive_point = search.pos;
    out.negative_point = search.neg;
    out.decided_by = step;
    return out;
  };

  // (1) Lineality L: c + t v stays in K for every v in L. A direction v of L with q(v) != 0 gives the sign
  // of q(v) (t large); a direction with q(v) = 0 and S(c, v) != 0 gives both signs (q is affine in t).
  // For the line-set cones of visibility queries L is spanned by one real line (the line common to the
  // planes of S and T), so this step always decides; other cones with lineality raise logic_error.
  if (!cone.lineality.empty()) {
    std::vector<IntVec6> lin;
    for (const auto& l : cone.lineality) lin.push_back(l.to_gmp());
    std::vector<IntVec6> dirs = lin;
    for (std::size_t i = 0; i < lin.size(); ++i)
      for (std::size_t j = i + 1; j < lin.size(); ++j) {
        dirs.push_back(combine(1, lin[i], 1, lin[j]));
        dirs.push_back(combine(1, lin[i], -1, lin[j]));
      }
    IntVec6 c = interior_point(cone);
    for (const auto& v : dirs) {
      const int s = sgn(plucker_form(v));
      if (s == 0) continue;
      for (mpz_class k = 1;; k *= 2) {
        const IntVec6 x = combine(1, c, k, v);
        if (sgn(plucker_form(x)) == s) {
          search.offer(x);
          break;
        }
      }
    }
    for (const auto& b : dirs) {
      if (search.done()) break;
      if (sgn(plucker_form(b)) != 0) continue;
      IntVec6 cc = c;
      mpz_class s = side6(cc, b);
      for (std::size_t j = 0; sgn(s) == 0 && j < cone.rays.size() + lin.size(); ++j) {
        const IntVec6 g = j < cone.rays.size() ? cone.rays[j].to_gmp() : lin[j - cone.rays.size()];
        const IntVec6 c2 = combine(1, c, 1, g);
        if (sgn(side6(c2, b)) != 0) {
          cc = c2;
          s = side6(c2, b);
        }
      }
      if (sgn(s) == 0) continue;
      const mpz_class k = abs(plucker_form(cc)) + 1;
      // q(cc + t b) = q(cc) + t s: t = +-k sign(s) gives q(cc) +- k |s|.
      search.offer(combine(1, cc, sgn(s) * k, b));
      search.offer(combine(1, cc, -sgn(s) * k, b));
    }
    if (!search.done()) throw std::logic_error("real-line test: undecided cone with lineality");
    return finish(1);
  }

  // (2) Signs at the rays.
  for (const auto& r : cone.rays) search.offer(r);
  if (search.done()) return finish(2);

  // (3) Two-dimensional faces spanned by ray pairs (sufficient, cheap).
  for (std::size_t i = 0; i < cone.rays.size() && !search.done(); ++i)
    for (std::size_t j = i + 1; j < cone.rays.size() && !search.done(); ++j) {
      if (!search.have_pos)
        if (auto p = pair_point(cone.rays[i], cone.rays[j], +1))
          search.offer(*p);
      if (!search.have_neg)
        if (auto p = pair_point(cone.rays[i], cone.rays[j], -1))
          search.offer(*p);
    }
  if (search.done()) return finish(3);
  // If q >= 0 at all rays and S(ri, rj) >= 0 for all pairs, q >= 0 on the cone: no negative point exists.
  // (pair_point found none of the missing sign: that already covers every pair.) Only step 4 can still
  // find the missing sign when some pair has a "wrong" S but not enough to change the sign on that pair.
  bool pairs_conclusive = true;
  for (std::size_t i = 0; i < cone.rays.size() && pairs_conclusive; ++i)
    for (std::size_t j = i + 1; j < cone.rays.size() && pairs_conclusive; ++j) {
      const int want = search.have_pos ? -1 : +1;
      if (want * side_sign(cone.rays[i], cone.rays[j]) > 0)
        pairs_conclusive = false;
    }
  if (pairs_conclusive) return finish(3);

  // (4) Stationary points of q on every face of dimension >= 2 (faces = ray sets, reached by intersecting
  // with constraint zero sets).
  const IntVec6 h = sum(cone.constraints);
  const std::size_t nr = cone.rays.size();
  std::vector<IntVec6> rays;
  for (const auto& r : cone.rays) rays.push_back(r.to_gmp());
  boost::dynamic_bitset<> all(nr);
  all.set();
  std::set<boost::dynamic_bitset<>> seen{all};
  std::deque<boost::dynamic_bitset<>> queue{all};
  while (!queue.empty() && !search.done()) {
    boost::dynamic_bitset<> face = queue.front();
    queue.pop_front();
    ++out.faces_examined;
    std::vector<const IntVec6*> members;
    for (std::size_t r = 0; r < nr; ++r)
      if (face[r]) members.push_back(&rays[r]);
    const auto idx = independent_subset(members);
    const std::size_t k = idx.size();
    if (k >= 2) {
      std::vector<std::vector<mpq_class>> g(k, std::vector<mpq_class>(k));
      std::vector<mpq_class> eta(k);
      for (std::size_t a = 0; a < k; ++a) {
        eta[a] = dot(h, *members[idx[a]]);
        for (std::size_t b = 0; b < k; ++b) g[a][b] = side6(*members[idx[a]], *members[idx[b]]);
      }
      std::vector<mpq_class> lambda;
      if (solve(g, eta, lambda)) {
        RatVec6 x;
        for (auto& c : x) c = 0;
        for (std::size_t a = 0; a < k; ++a)
          for (int j = 0; j < 6; ++j) x[j] += lambda[a] * (*members[idx[a]])[j];
        IntVec6 xi = to_integer(x);
        if (!is_zero(xi)) {
          if (in_closure(cone, xi)) search.offer(xi);
          else if (in_closure(cone, negated(xi))) search.offer(negated(xi));
        }
      }
    }
    for (std::size_t i = 0; i < cone.constraints.size(); ++i) {
      boost::dynamic_bitset<> sub = face;
      for (std::size_t r = 0; r < nr; ++r)
        if (sub[r] && !cone.incidence[r][i]) sub[r] = false;
      if (sub == face || sub.count() < 2) continue;
      if (seen.insert(sub).second) queue.push_back(sub);
    }
  }
  return finish(4);
}

}  // namespace exactvis::region
