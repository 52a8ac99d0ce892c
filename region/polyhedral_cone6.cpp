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
    IncidenceSet b(keep.size());
    for (std::size_t k = 0; k < keep.size(); ++k) b.set(k, inc[keep[k]]);
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
  auto widen = [&](const IncidenceSet& inc, bool on_new) {
    IncidenceSet b = inc;
    b.resize(n_old + 1);
    b.set(n_old, on_new);
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
    IncidenceSet inc(n_old + 1);
    inc.set_all();
    inc.set(n_old, false);
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
  IncidenceSet common(n_old);
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

HyperplaneSigns hyperplane_signs(const PolyhedralCone6& cone, const ConeVector6& w) {
  HyperplaneSigns out;
  for (const auto& b : cone.lineality)
    if (dot_sign(w, b) != 0) {
      out.relation = HalfspaceRelation::Crossing;
      out.by_lineality = true;
      return out;
    }
  bool pos = false, neg = false;
  out.ray_signs.resize(cone.rays.size());
  for (std::size_t r = 0; r < cone.rays.size(); ++r) {
    const int s = dot_sign(w, cone.rays[r]);
    out.ray_signs[r] = static_cast<signed char>(s);
    pos |= s > 0;
    neg |= s < 0;
  }
  out.relation = pos && neg ? HalfspaceRelation::Crossing : (pos ? HalfspaceRelation::Inside : HalfspaceRelation::Outside);
  return out;
}

std::array<PolyhedralCone6, 2> split_crossing(const PolyhedralCone6& cone, const ConeVector6& w,
                                              const HyperplaneSigns& signs) {
  if (signs.relation != HalfspaceRelation::Crossing || signs.by_lineality)
    throw std::logic_error("split_crossing: the hyperplane does not cross the cone through its rays");
  const std::size_t n_old = cone.constraints.size();
  const auto& sign = signs.ray_signs;
  std::array<PolyhedralCone6, 2> out;
  out[0].constraints.reserve(n_old + 1);
  out[0].constraints = cone.constraints;
  out[0].constraints.push_back(w);
  out[1].constraints.reserve(n_old + 1);
  out[1].constraints = cone.constraints;
  out[1].constraints.push_back(w.negated());
  for (auto& o : out) o.lineality = cone.lineality;
  auto widen = [&](const IncidenceSet& inc, bool on_new) {
    IncidenceSet b = inc;
    b.resize(n_old + 1);
    b.set(n_old, on_new);
    return b;
  };
  // Kept rays, in order, as intersect_open_halfspace keeps them: part 0 keeps sign >= 0, part 1 sign <= 0.
  for (std::size_t r = 0; r < cone.rays.size(); ++r) {
    for (int part = 0; part < 2; ++part) {
      const int s = part == 0 ? sign[r] : -sign[r];
      if (s < 0) continue;
      out[part].rays.push_back(cone.rays[r]);
      out[part].incidence.push_back(widen(cone.incidence[r], s == 0));
    }
  }
  // New rays: part 0 lists them by (p with w.p > 0, q with w.q < 0) in loop order, part 1 by (p with
  // w.p < 0, q with w.q > 0). Computed once, in part 0's order, then placed in part 1's order.
  const std::size_t dim = 6 - cone.lineality.size();
  const std::size_t nr = cone.rays.size();
  std::vector<std::size_t> pos_rays, neg_rays;
  for (std::size_t r = 0; r < nr; ++r) {
    if (sign[r] > 0) pos_rays.push_back(r);
    else if (sign[r] < 0) neg_rays.push_back(r);
  }
  // pair_ray[a * neg_rays.size() + b]: index into out[0].rays of the ray of (pos_rays[a], neg_rays[b]), or -1.
  std::vector<std::ptrdiff_t> pair_ray(pos_rays.size() * neg_rays.size(), -1);
  std::vector<IncidenceSet> pair_common(pos_rays.size() * neg_rays.size());
  IncidenceSet common(n_old);
  for (std::size_t a = 0; a < pos_rays.size(); ++a) {
    const std::size_t p = pos_rays[a];
    for (std::size_t b = 0; b < neg_rays.size(); ++b) {
      const std::size_t q = neg_rays[b];
      common = cone.incidence[p];
      common &= cone.incidence[q];
      if (dim >= 2 && common.count() + 2 < dim) continue;
      bool adjacent = true;
      for (std::size_t r = 0; r < nr && adjacent; ++r)
        if (r != p && r != q && common.is_subset_of(cone.incidence[r])) adjacent = false;
      if (!adjacent) continue;
      pair_ray[a * neg_rays.size() + b] = static_cast<std::ptrdiff_t>(out[0].rays.size());
      out[0].rays.push_back(eliminate(w, cone.rays[p], cone.rays[q]));
      out[0].incidence.push_back(widen(common, true));
    }
  }
  // Part 1's loop: p over the negative rays (outer), q over the positive ones; the vector of the pair is
  // eliminate(-w, rq', rp') = (w.p) q - (w.q) p for the same pair: the one computed above.
  for (std::size_t b = 0; b < neg_rays.size(); ++b)
    for (std::size_t a = 0; a < pos_rays.size(); ++a) {
      const std::ptrdiff_t i = pair_ray[a * neg_rays.size() + b];
      if (i < 0) continue;
      out[1].rays.push_back(out[0].rays[static_cast<std::size_t>(i)]);
      out[1].incidence.push_back(out[0].incidence[static_cast<std::size_t>(i)]);
    }
  drop_redundant_constraints(out[0]);
  drop_redundant_constraints(out[1]);
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
