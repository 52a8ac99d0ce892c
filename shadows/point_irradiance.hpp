#pragma once
// Unoccluded irradiance at a receiver point from the visible part of a Lambertian area light (docs/theory.md
// section 11, "Irradiance"): Lambert's polygon-to-point form factor
//   F = 1/(2 pi) | sum over boundary edges (v_i, v_j) of theta_ij * n . (r_i x r_j) / |r_i x r_j| |,
// r = v - p, theta_ij the angle between r_i and r_j, n the receiver's unit normal, summed over the outer
// loop and the holes of every visible piece (per light triangle, then added). The light has exitance 1
// (irradiance = F, in units of the light's exitance) and emits from both faces; the receiver is two-sided:
// n is oriented towards the light's vertex centroid, and the visible polygons are first clipped exactly to the
// closed half-space in front of the receiver's plane through p. The polygons are exact; the formula is
// evaluated in double precision (acos/atan2 are not rational).
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "shadows/backprojection.hpp"

namespace exactvis::shadows {

// Input: scene (for the light's vertices), p, the receiver's plane normal (any length, exact), the
// backprojection at p. Output: F >= 0 (double). Cost: linear in the visible polygons' size.
double point_irradiance(const Scene& scene, const RationalPoint3& p, const Vec3<Exact>& receiver_normal,
                        const Backprojection& bp);

// The same formula for one closed loop of exact points (no clipping), signed by the loop's orientation about
// n (n a unit normal in doubles). Exposed for tests.
double lambert_loop_sum(const Point3& p, const Point3& n, const std::vector<RationalPoint3>& loop);

}  // namespace exactvis::shadows
