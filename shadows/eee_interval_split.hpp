#pragma once
// Exact splitting of EEE free intervals where the objects at the ends of their lines change
// (docs/theory.md section 11, "Exact EEE end objects"): the EEE counterpart of events/ev_interval_split.hpp.
//
// For a free interval [t0, t1] of an EEE family L(t), the first closed triangle hit beyond each outermost
// generator point (front: along d = Q2 - P, back: along -d) is piecewise constant in t. It can change only
// where L(t) meets the line of an edge of a triangle the lines reach (a quadratic in t: EEEE lines, roots in
// Q(sqrt D)), or the line in which two triangles cross (the first hit passes from one to the other there).
// The split collects the first kind from every triangle meeting an interval enclosure of the lines' part
// inside the scene box (an interval filter drops edges whose polynomial has no root in the range), decides
// the objects exactly (kernel/ray_first_hit.hpp) at a rational sample of each gap between consecutive roots,
// adds the second kind for the objects found there and recurses, and merges equal neighbours.
#include "events/eee_events.hpp"
#include "kernel/number_types.hpp"
#include "kernel/quadratic_polynomial.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::shadows {

// Plücker coordinates (d(t), m(t)) of the lines L(t) of an EEE family, each coordinate a polynomial of degree
// <= 2 in t with exact rational coefficients: d(t) is eee_line_points' direction, m(t) = P(t) x d(t). Built
// from eee_line_points at t = 0, 1/2, 1 (a local wrapper until events/ exposes its own polynomials).
struct EeeLinePolynomials {
  Vec3<QuadraticPolynomial> d, m;
};
EeeLinePolynomials eee_line_polynomials(const Scene& scene, const EeeEvent& event);

// side(L(t), line(a, b)) as a polynomial in t (zero where L(t) meets the line through a and b, or is parallel
// to it). Exact.
QuadraticPolynomial eee_side_polynomial(const EeeLinePolynomials& lines, const Vec3<Exact>& a, const Vec3<Exact>& b);

// A piece of a free interval on which both end objects are constant.
struct EeeEndPiece {
  RootNumber t0, t1;                       // exact; consecutive pieces share an end
  Exact sample_t;                          // rational, strictly inside (t0, t1)
  std::int64_t front = -1, back = -1;      // stable triangle ids (-1: the ray leaves the scene)
};

struct EeeSplitStats {
  std::uint64_t candidates = 0;   // triangles examined
  std::uint64_t polynomials = 0;  // edge and crossing polynomials solved exactly (after the interval filter)
  std::uint64_t gaps = 0;         // exact end-object evaluations (two ray_first_hit each)
};

// Input: the scene, its spatial index and bounding box, an EEE event and one of its free intervals.
// Output: consecutive pieces covering [interval.t0, interval.t1] (at least one), neighbours differing in at
// least one object; on the open piece (t0, t1) the objects are the given ones for every t. Exact. Cost: one
// box query, three interval-filtered quadratics per candidate, two exact ray casts per gap.
std::vector<EeeEndPiece> split_eee_interval(const Scene& scene, const TriangleIndex& index, const Box3& box,
                                            const EeeEvent& event, const CriticalInterval& interval,
                                            EeeSplitStats* stats = nullptr);

}  // namespace exactvis::shadows
