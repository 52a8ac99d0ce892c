#pragma once
// The CGAL kernel of the shadows module's planar work (Boolean set operations, constrained triangulations):
// Cartesian over a lazy exact rational, every construction and predicate exact (see aspect/aspect_graph_2d
// for why not Epeck), and conversions from and to the project's Exact rationals.
#include "kernel/number_types.hpp"

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <gmpxx.h>

#include <array>

namespace exactvis::shadows {

using PlanarKernel = CGAL::Simple_cartesian<CGAL::Lazy_exact_nt<mpq_class>>;
using PlanarPoint = PlanarKernel::Point_2;

inline PlanarKernel::FT to_planar_ft(const Exact& x) { return PlanarKernel::FT(mpq_class(x.mpq())); }
inline Exact from_planar_ft(const PlanarKernel::FT& x) {
  const mpq_class q = CGAL::exact(x);
  return Exact(q.get_mpq_t());
}
inline PlanarPoint to_planar(const std::array<Exact, 2>& p) { return {to_planar_ft(p[0]), to_planar_ft(p[1])}; }
inline std::array<Exact, 2> from_planar(const PlanarPoint& p) { return {from_planar_ft(p.x()), from_planar_ft(p.y())}; }

}  // namespace exactvis::shadows
