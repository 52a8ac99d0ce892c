#pragma once
// The sampled PVS of one view cell (method `sampled` of `exactvis pvs`, issue #12): an aggressive baseline.
//
// Random rays from the cell (origins uniform in the cell, directions uniform on the sphere) are cast with
// Embree (kernel/float_ray_caster.hpp); the first triangle a ray hits is a *proposal*: it is listed only when
// the segment from the ray's origin to the hit point (an exact point of the triangle's relative interior,
// from Embree's barycentric coordinates) passes the exact acceptance test of region/ray_witness.hpp (origin
// in the open cell, closed segment missing every other closed triangle, hence visible with positive
// measure). So the sampled PVS never lists a hidden triangle; it errs only by missing visible ones (small,
// distant or seen through narrow gaps), as aggressive methods do.
#include "region/cell_pvs.hpp"

namespace exactvis::region {

// Input: the context, a cell (lo < hi, else std::invalid_argument), options: `cell_rays` rays per cell,
// query.seed, threads. Output: the confirmed triangles (sorted by index, each with its exact witness: the
// confirmed ray segment, rounded to doubles when the rounded segment passes the same test); stats.rays_cast,
// stats.accepted_by_rays = visible, stats.seconds. Deterministic for a given seed, whatever the thread count
// (rays are drawn in fixed chunks, each triangle keeps the witness of its first confirming ray). Cost:
// cell_rays Embree rays plus one exact segment check per proposal of a triangle not yet confirmed in its
// chunk.
CellPvs sampled_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options);

}  // namespace exactvis::region
