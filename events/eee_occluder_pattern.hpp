#pragma once
// Interval layer of the exact occluder analysis of an EEE family (docs/theory.md section 6, "Breakpoints and
// exact decisions", and section 9, "Scale"): the floating-point filter in front of eee_event's Gmpq analysis
// of one occluder over the current range [vmin, vmax].
//
// The exact analysis sorts the real roots, strictly inside (vmin, vmax), of the occluder's polynomials — the
// three side polynomials q_k(t) = side(L(t), e_k) (quadratic), the three heights of the generator points
// over its plane (linear; Q2, Q3 homogeneous) and den2, den3 (linear) — decides each open gap between
// consecutive breakpoints by the sign function of its polynomials at a rational sample, and each rational
// breakpoint by an exact segment-triangle test. This class finds the same *pattern* with interval arithmetic
// only: enclosures of every root inside the range (all pairwise disjoint and disjoint from the enclosures of
// vmin and vmax, so the sorted order is certain and no two breakpoints coincide), each gap's status from
// certified signs at a double sample inside it, and each breakpoint's status from the sign function there
// (its own polynomial zero, the others with the signs of the gap before it; the line is then not in the
// occluder's plane, where the sign function is the segment-triangle test). eee_event then builds exact
// roots only for the breakpoints that end a blocked gap or are blocked themselves, and produces the same
// invalid pieces as the exact analysis. Anything not certified (roots close to each other or to the range
// ends, signs too close to 0) returns std::nullopt and the exact analysis runs: rounding never decides.
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace exactvis {

// Which polynomial of the occluder analysis a breakpoint is a root of.
enum class EeeOccluderPoly : int {
  Side = 0,    // q_k = side(L(t), line(c_k, c_k+1)): `index` = k
  Height = 1,  // height over the occluder's plane of generator point `index` (0: P, 1: Q2, 2: Q3)
  Den = 2,     // den_k (L(t) parallel to E_k's line): `index` = k in {1, 2}
};

// One breakpoint strictly inside (vmin, vmax).
struct EeeOccluderBreakpoint {
  EeeOccluderPoly poly = EeeOccluderPoly::Side;
  int index = 0;
  int rank = 0;          // rank of this root among the roots of that polynomial inside (vmin, vmax), from 0
  bool blocked = false;  // the generator segment of the line at this parameter meets the closed occluder
};

// The certified result: breakpoints in increasing order and the status of the inner.size() + 1 open gaps
// between vmin, the breakpoints and vmax. One assumption may remain, to be checked exactly by the caller: a
// root whose enclosure meets the enclosure of vmin (or vmax) is taken to be not inside (vmin, vmax) — an
// exact tie, typical of an occluder sharing an edge line with the one that cut the range there. The
// polynomials with such roots are listed in `verify`: the pattern holds iff each of them has exactly as many
// roots strictly inside (vmin, vmax) as `inner` lists for it (the enclosures already prove that many).
struct EeeOccluderPattern {
  std::vector<EeeOccluderBreakpoint> inner;
  std::vector<char> gap_blocked;
  std::vector<EeeOccluderBreakpoint> verify;  // poly and index of each polynomial to check (rank unused)
  bool blocks_nothing() const;  // no gap and no breakpoint blocked
};

class EeeOccluderPatternFilter {
 public:
  // [axis][degree] coefficients of a vector polynomial of degree <= 2 in t (exact).
  using VecPoly = std::array<std::array<Exact, 3>, 3>;
  using ScalarPoly = std::array<Exact, 3>;
  // Input: the family's exact polynomials (eee_events.cpp's Family): P(t), the homogeneous meeting points
  // (num_k : den_k) for k = 1, 2, and L(t)'s Plücker coordinates (Ld, Lm). Cost: 45 interval enclosures.
  EeeOccluderPatternFilter(const VecPoly& p, const VecPoly& num1, const ScalarPoly& den1, const VecPoly& num2,
                           const ScalarPoly& den2, const VecPoly& ld, const VecPoly& lm);

  // The pattern of the closed triangle (a, b, c) (a scene triangle with double corners) over (vmin, vmax),
  // given enclosures of vmin < vmax; std::nullopt when not certified (see the header comment), always when
  // the filter is off (set_filter_enabled). Counted as predicate "eee_occluder_pattern" (interval layer:
  // certified; exact layer: not certified, the exact analysis runs). Thread-safe for concurrent const calls.
  // Cost: about 300 interval operations.
  std::optional<EeeOccluderPattern> pattern(const Point3& a, const Point3& b, const Point3& c,
                                            const std::pair<double, double>& vmin,
                                            const std::pair<double, double>& vmax) const;

 private:
  using Enclosure = std::array<double, 2>;          // [lo, hi]
  using IPoly = std::array<Enclosure, 3>;           // [degree]
  std::array<IPoly, 3> p_{}, num_[2]{}, ld_{}, lm_{};  // [axis]
  IPoly den_[2]{};
};

}  // namespace exactvis
