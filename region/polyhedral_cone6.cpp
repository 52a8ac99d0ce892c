#include "region/polyhedral_cone6.hpp"

#include <stdexcept>

namespace exactvis::region {

PolyhedralCone6 whole_space_cone() {
  PolyhedralCone6 c;
  for (int i = 0; i < 6; ++i) {
    IntVec6 e;
    for (int j = 0; j < 6; ++j) e[j] = (i == j) ? 1 : 0;
    c.lineality.push_back(e);
    c.lineality_approx.push_back(approximate(e));
  }
  return c;
}

HalfspaceRelation relation_to_halfspace(const PolyhedralCone6& cone, const IntVec6& w) {
  return relation_to_halfspace(cone, w, approximate(w));
}

HalfspaceRelation relation_to_halfspace(const PolyhedralCone6& cone, const IntVec6& w, const Approx6& wa) {
  for (std::size_t j = 0; j < cone.lineality.size(); ++j)
    if (dot_sign(w, wa, cone.lineality[j], cone.lineality_approx[j]) != 0) return HalfspaceRelation::Crossing;
  bool pos = false, neg = false;
  for (std::size_t r = 0; r < cone.rays.size(); ++r) {
    const int s = dot_sign(w, wa, cone.rays[r], cone.rays_approx[r]);
    pos |= s > 0;
    neg |= s < 0;
    if (pos && neg) return HalfspaceRelation::Crossing;
  }
  if (pos) return HalfspaceRelation::Inside;
  if (neg) return HalfspaceRelation::Outside;
  // w vanishes on the whole closure: K (full-dimensional) would make w = 0.
  return HalfspaceRelation::Outside;
}

namespace {

// Drop constraints that cannot define a facet (too few incident rays); they are implied by the others on
// the closure, and then also on the open cone because K is the interior of its closure.
void drop_redundant_constraints(PolyhedralCone6& cone) {
  const std::size_t dim = 6 - cone.lineality.size();
  if (dim < 2) return;
  const std::size_t n = cone.constraints.size();
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t count = 0;
    for (const auto& inc : cone.incidence) count += inc[i] ? 1 : 0;
    if (count + 1 >= dim) keep.push_back(i);  // a facet of a dim-dimensional pointed cone has >= dim-1 rays
  }
  if (keep.size() == n) return;
  std::vector<IntVec6> constraints;
  for (auto i : keep) constraints.push_back(cone.constraints[i]);
  for (auto& inc : cone.incidence) {
    boost::dynamic_bitset<> b(keep.size());
    for (std::size_t k = 0; k < keep.size(); ++k) b[k] = inc[keep[k]];
    inc = std::move(b);
  }
  cone.constraints = std::move(constraints);
}

}  // namespace

std::optional<PolyhedralCone6> intersect_open_halfspace(const PolyhedralCone6& cone, const IntVec6& w) {
  return intersect_open_halfspace(cone, w, approximate(w));
}

std::optional<PolyhedralCone6> intersect_open_halfspace(const PolyhedralCone6& cone, const IntVec6& w,
                                                        const Approx6& wa) {
  const std::size_t n_old = cone.constraints.size();
  PolyhedralCone6 out;
  out.constraints = cone.constraints;
  out.constraints.push_back(w);
  auto widen = [&](const boost::dynamic_bitset<>& inc, bool on_new) {
    boost::dynamic_bitset<> b = inc;
    b.resize(n_old + 1);
    b[n_old] = on_new;
    return b;
  };

  // Case 1: the hyperplane cuts the lineality space: one lineality direction becomes a ray.
  std::size_t pivot = cone.lineality.size();
  for (std::size_t j = 0; j < cone.lineality.size(); ++j)
    if (dot_sign(w, wa, cone.lineality[j], cone.lineality_approx[j]) != 0) {
      pivot = j;
      break;
    }
  if (pivot < cone.lineality.size()) {
    mpz_class wb = dot(w, cone.lineality[pivot]);
    IntVec6 b = cone.lineality[pivot];
    if (sgn(wb) < 0) {
      for (auto& c : b) c = -c;
      wb = -wb;
    }
    for (std::size_t j = 0; j < cone.lineality.size(); ++j) {
      if (j == pivot) continue;
      const mpz_class wj = dot(w, cone.lineality[j]);
      IntVec6 v;
      for (int k = 0; k < 6; ++k) v[k] = wb * cone.lineality[j][k] - wj * b[k];
      normalize(v);
      out.lineality_approx.push_back(approximate(v));
      out.lineality.push_back(std::move(v));
    }
    for (std::size_t r = 0; r < cone.rays.size(); ++r) {
      const mpz_class wr = dot(w, cone.rays[r]);
      IntVec6 v;
      for (int k = 0; k < 6; ++k) v[k] = wb * cone.rays[r][k] - wr * b[k];
      normalize(v);
      out.rays_approx.push_back(approximate(v));
      out.rays.push_back(std::move(v));
      out.incidence.push_back(widen(cone.incidence[r], true));
    }
    out.rays_approx.push_back(approximate(b));
    out.rays.push_back(b);
    boost::dynamic_bitset<> inc(n_old + 1);
    inc.set();
    inc[n_old] = false;
    out.incidence.push_back(inc);
    drop_redundant_constraints(out);
    return out;
  }

  // Case 2: classify the rays.
  std::vector<int> sign(cone.rays.size());
  bool any_pos = false, any_neg = false;
  for (std::size_t r = 0; r < cone.rays.size(); ++r) {
    sign[r] = dot_sign(w, wa, cone.rays[r], cone.rays_approx[r]);
    any_pos |= sign[r] > 0;
    any_neg |= sign[r] < 0;
  }
  if (!any_pos) return std::nullopt;  // the open cone misses {w > 0}
  if (!any_neg) return cone;          // already inside: nothing changes (w would be redundant)

  out.lineality = cone.lineality;
  out.lineality_approx = cone.lineality_approx;
  // Exact values w . r, only for the rays that are combined.
  std::vector<std::optional<mpz_class>> value(cone.rays.size());
  auto value_of = [&](std::size_t r) -> const mpz_class& {
    if (!value[r]) value[r] = dot(w, cone.rays[r]);
    return *value[r];
  };
  const std::size_t dim = 6 - cone.lineality.size();
  for (std::size_t r = 0; r < cone.rays.size(); ++r) {
    if (sign[r] < 0) continue;
    out.rays.push_back(cone.rays[r]);
    out.rays_approx.push_back(cone.rays_approx[r]);
    out.incidence.push_back(widen(cone.incidence[r], sign[r] == 0));
  }
  for (std::size_t p = 0; p < cone.rays.size(); ++p) {
    if (sign[p] <= 0) continue;
    for (std::size_t q = 0; q < cone.rays.size(); ++q) {
      if (sign[q] >= 0) continue;
      const boost::dynamic_bitset<> common = cone.incidence[p] & cone.incidence[q];
      if (dim >= 2 && common.count() + 2 < dim) continue;
      bool adjacent = true;
      for (std::size_t r = 0; r < cone.rays.size() && adjacent; ++r)
        if (r != p && r != q && common.is_subset_of(cone.incidence[r])) adjacent = false;
      if (!adjacent) continue;
      IntVec6 v;
      const mpz_class &vp = value_of(p), &vq = value_of(q);
      for (int k = 0; k < 6; ++k) v[k] = vp * cone.rays[q][k] - vq * cone.rays[p][k];
      normalize(v);
      out.rays_approx.push_back(approximate(v));
      out.rays.push_back(std::move(v));
      out.incidence.push_back(widen(common, true));
    }
  }
  drop_redundant_constraints(out);
  return out;
}

IntVec6 interior_point(const PolyhedralCone6& cone) {
  IntVec6 c;
  for (auto& x : c) x = 0;
  for (const auto& r : cone.rays)
    for (int k = 0; k < 6; ++k) c[k] += r[k];
  return c;
}

bool in_closure(const PolyhedralCone6& cone, const IntVec6& x) {
  for (const auto& w : cone.constraints)
    if (sgn(dot(w, x)) < 0) return false;
  return true;
}

bool in_open_cone(const PolyhedralCone6& cone, const IntVec6& x) {
  for (const auto& w : cone.constraints)
    if (sgn(dot(w, x)) <= 0) return false;
  return true;
}

}  // namespace exactvis::region
