#include "region/polyhedral_cone6.hpp"

#include <stdexcept>

namespace exactvis::region {

PolyhedralCone6 whole_space_cone() {
  PolyhedralCone6 c;
  for (std::size_t i = 0; i < 6; ++i) {
    Fixed6 e{};
    e[i] = 1;
    c.lineality.emplace_back(e);
  }
  return c;
}

HalfspaceRelation relation_to_halfspace(const PolyhedralCone6& cone, const IntVec6& w) {
  return relation_to_halfspace(cone, ConeVector6(w));
}

HalfspaceRelation relation_to_halfspace(const PolyhedralCone6& cone, const ConeVector6& w) {
  for (const auto& b : cone.lineality)
    if (dot_sign(w, b) != 0) return HalfspaceRelation::Crossing;
  bool pos = false, neg = false;
  for (const auto& r : cone.rays) {
    const int s = dot_sign(w, r);
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
  std::vector<ConeVector6> constraints;
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
  return intersect_open_halfspace(cone, ConeVector6(w));
}

std::optional<PolyhedralCone6> intersect_open_halfspace(const PolyhedralCone6& cone, const ConeVector6& w) {
  const std::size_t n_old = cone.constraints.size();
  PolyhedralCone6 out;
  auto widen = [&](const boost::dynamic_bitset<>& inc, bool on_new) {
    boost::dynamic_bitset<> b = inc;
    b.resize(n_old + 1);
    b[n_old] = on_new;
    return b;
  };

  // Case 1: the hyperplane cuts the lineality space: one lineality direction becomes a ray.
  std::size_t pivot = cone.lineality.size();
  int pivot_sign = 0;
  for (std::size_t j = 0; j < cone.lineality.size(); ++j)
    if ((pivot_sign = dot_sign(w, cone.lineality[j])) != 0) {
      pivot = j;
      break;
    }
  if (pivot < cone.lineality.size()) {
    out.constraints = cone.constraints;
    out.constraints.push_back(w);
    // b: the pivot oriented so that w . b > 0; every other generator x becomes (w . b) x - (w . x) b.
    const ConeVector6 b = pivot_sign < 0 ? cone.lineality[pivot].negated() : cone.lineality[pivot];
    for (std::size_t j = 0; j < cone.lineality.size(); ++j)
      if (j != pivot) out.lineality.push_back(eliminate(w, b, cone.lineality[j]));
    for (std::size_t r = 0; r < cone.rays.size(); ++r) {
      out.rays.push_back(eliminate(w, b, cone.rays[r]));
      out.incidence.push_back(widen(cone.incidence[r], true));
    }
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
    sign[r] = dot_sign(w, cone.rays[r]);
    any_pos |= sign[r] > 0;
    any_neg |= sign[r] < 0;
  }
  if (!any_pos) return std::nullopt;  // the open cone misses {w > 0}
  if (!any_neg) return cone;          // already inside: nothing changes (w would be redundant)

  out.constraints = cone.constraints;
  out.constraints.push_back(w);
  out.lineality = cone.lineality;
  const std::size_t dim = 6 - cone.lineality.size();
  for (std::size_t r = 0; r < cone.rays.size(); ++r) {
    if (sign[r] < 0) continue;
    out.rays.push_back(cone.rays[r]);
    out.incidence.push_back(widen(cone.incidence[r], sign[r] == 0));
  }
  boost::dynamic_bitset<> common(n_old);  // reused for every pair: assignment keeps its storage
  for (std::size_t p = 0; p < cone.rays.size(); ++p) {
    if (sign[p] <= 0) continue;
    for (std::size_t q = 0; q < cone.rays.size(); ++q) {
      if (sign[q] >= 0) continue;
      common = cone.incidence[p];
      common &= cone.incidence[q];
      if (dim >= 2 && common.count() + 2 < dim) continue;
      bool adjacent = true;
      for (std::size_t r = 0; r < cone.rays.size() && adjacent; ++r)
        if (r != p && r != q && common.is_subset_of(cone.incidence[r])) adjacent = false;
      if (!adjacent) continue;
      // (w . rp) rq - (w . rq) rp: positive combination (w . rp > 0 > w . rq) on the hyperplane.
      out.rays.push_back(eliminate(w, cone.rays[p], cone.rays[q]));
      out.incidence.push_back(widen(common, true));
    }
  }
  drop_redundant_constraints(out);
  return out;
}

IntVec6 interior_point(const PolyhedralCone6& cone) { return sum(cone.rays); }

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
