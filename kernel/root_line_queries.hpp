#pragma once
// Exact queries on lines over Q(sqrt D) (the results of lines_through_four_lines) against rational lines.
#include "kernel/plucker_line.hpp"
#include "kernel/root_number.hpp"

#include <optional>

namespace exactvis {

// Exact sign of side(x, l): how the transversal x passes the rational line l (section 2 convention).
Sign side_sign(const PluckerLine<RootNumber>& x, const PluckerLine<Exact>& l);

// The point where the real lines x and l meet, exactly in Q(sqrt D)^3; nullopt if they do not meet at a
// finite point (side != 0: skew; or parallel, including equal). Computed as O + (m' x m_l') / (m' . d_l)
// with moments m' about an origin O in {0, e_x, e_y, e_z} chosen off the lines' common plane.
std::optional<Vec3<RootNumber>> meeting_point(const PluckerLine<RootNumber>& x, const PluckerLine<Exact>& l);

}  // namespace exactvis
