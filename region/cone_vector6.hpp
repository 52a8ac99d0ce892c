#pragma once
// Exact integer 6-vectors of the line-set cones in two storage layers, with the float filter in front
// (docs/theory.md §5.4, "Fixed-width layer"), after geogram's predicate kit: every sign or construction is
// tried in the cheapest layer that is proved to give the exact result, and each layer is counted.
//
//   filter: doubles with a certified error bound (int_vector6's semi-static filter); signs only;
//   fixed:  int64 components, arithmetic in __int128 with every product and sum overflow-checked
//           (__builtin_*_overflow); an overflow never yields a value, it sends the operation to gmp;
//   gmp:    GMP integers (IntVec6), shared and immutable, for vectors with a component beyond int64.
//
// A vector is stored in the fixed layer whenever every component fits in [-(2^63 - 1), 2^63 - 1], so
// copies of cones (their rays and constraints) are plain memory copies and the hot paths allocate nothing.
// The value of a vector never depends on its layer: to_gmp() is the same integer vector either way, and the
// constructions return the same gcd-normalised vector as the GMP code of int_vector6.
#include "region/int_vector6.hpp"

#include <array>
#include <cstdint>
#include <memory>

namespace exactvis::region {

using Fixed6 = std::array<std::int64_t, 6>;

class ConeVector6 {
 public:
  // The zero vector (fixed layer).
  ConeVector6() = default;
  // Requires every component != INT64_MIN (so that negation stays in the layer).
  explicit ConeVector6(const Fixed6& v);
  // The fixed layer when every component fits, else the gmp layer (one shared copy of v).
  explicit ConeVector6(const IntVec6& v);

  bool is_fixed() const { return !big_; }
  const Fixed6& fixed() const { return fixed_; }  // requires is_fixed()
  const IntVec6& gmp() const { return *big_; }    // requires !is_fixed()
  // The vector as GMP integers (allocates; for the rare exact paths and for tests).
  IntVec6 to_gmp() const;
  // Double approximations (relative error < 2^-52 per component, docs/theory.md §5.4).
  const Approx6& approx() const { return approx_; }
  bool is_zero() const;
  ConeVector6 negated() const;
  // Same integer vector (whatever the layers).
  friend bool operator==(const ConeVector6& a, const ConeVector6& b);

 private:
  Fixed6 fixed_{};
  std::shared_ptr<const IntVec6> big_;
  Approx6 approx_{};
};

// Exact signs of a . b, side(a, b) and q(a) = d . m: filter, then fixed (__int128, checked), then gmp.
// Counted in the predicate counters "cone_dot", "cone_side", "cone_plucker_form" (semi_static = filter,
// exact = fixed or gmp) and in the layer counts below. Cost: a few flops; allocation-free unless gmp.
int dot_sign(const ConeVector6& a, const ConeVector6& b);
int side_sign(const ConeVector6& a, const ConeVector6& b);
int plucker_form_sign(const ConeVector6& a);

// The exact value a . x (x in GMP integers): for the exact re-checks of points against the constraints.
mpz_class dot(const ConeVector6& a, const IntVec6& x);

// One double-description combination (region/polyhedral_cone6): v = (w . p) q - (w . q) p, divided by the
// gcd of its components (the zero vector stays zero). v . w = 0; for w . p > 0 > w . q, v is a positive
// combination of p and q. The same vector as the GMP computation followed by normalize(). Fixed layer when
// w, p, q are fixed and no step overflows (w . p and w . q are first divided by their gcd, which keeps the
// direction and avoids most overflows of the products); otherwise gmp.
ConeVector6 eliminate(const ConeVector6& w, const ConeVector6& p, const ConeVector6& q);

// Sum of the vectors (exact, GMP; the interior point of a cone).
IntVec6 sum(const std::vector<ConeVector6>& vs);

// The side functional of the directed line through the points a and b given as doubles (docs/theory.md §5.4):
// the gcd-normalised integer vector proportional (positive factor) to (m, d) with d = b - a, m = a x b; the
// same vector as side_functional(line_through(a, b)) on the exact conversions. Computed in the fixed layer:
// each coordinate is an integer multiple of 2^-s for the smallest such s (the doubles' exponents); it
// returns false (and leaves `out` alone) when a == b, when a scaled coordinate or a product does not fit in
// 63 / 127 bits, or when the normalised result has a component beyond int64; the caller then takes the
// exact rational path.
bool side_functional_of_doubles(const Point3& a, const Point3& b, ConeVector6& out);

// How many cone operations each layer decided, totals over all threads: the predicate counters
// "cone_sign_filter", "cone_sign_fixed", "cone_sign_gmp" (every dot / side / q sign, ConeVector6 or IntVec6
// inputs) and "cone_construction_fixed", "cone_construction_gmp" (eliminate, side_functional_of_doubles),
// each counting in its `calls` column (kernel/predicate_counters.hpp: reset with reset_predicate_counters()).
// O(counters), takes a lock: not for hot loops.
enum class ConeLayer : int { Filter = 0, Fixed = 1, Gmp = 2 };
struct ConeLayerCounts {
  std::uint64_t signs[3] = {0, 0, 0};          // by ConeLayer
  std::uint64_t constructions[3] = {0, 0, 0};  // Fixed and Gmp (Filter unused)
};
ConeLayerCounts cone_layer_counts();
// One decision of a sign / construction by `layer` (thread-local, allocation-free).
void count_cone_sign(ConeLayer layer);
void count_cone_construction(ConeLayer layer);

}  // namespace exactvis::region
