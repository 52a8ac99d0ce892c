#pragma once
// BoundedDouble: the number type of the semi-static filter layer of filtered_sign for any predicate
// expression (sums, differences and products): a double evaluated in the default rounding mode together
// with a proven bound on its distance to the exact value. No rounding-mode switch, no branch on signs.
//
// Representation of a value x: the computed double v, a magnitude m and an index k with
//     |v| <= m   and   |v - x| <= g(k) * m,   g(k) = (1 - u)^-k - 1,  u = 2^-53,
// maintained operation by operation (the rules and their proof: docs/theory.md section 1, "Semi-static
// layer"). m is computed like v with |operands| and + only, so it costs one more flop per operation.
// certified_sign() returns the sign of x when |v| exceeds the bound, and Zero when m == 0 (then x = 0).
// Overflow, and products whose magnitude leaves the normal range (where the relative error model of
// IEEE arithmetic fails), make m infinite or NaN: such values never certify anything.
//
// Preconditions (docs/theory.md section 1): IEEE binary64 with round-to-nearest (the default mode; never
// evaluate inside a CGAL::Protect_FPU_rounding scope), gradual underflow, no -ffast-math. FMA contraction
// is harmless (a fused multiply-add rounds once where the rules allow twice).
#include "kernel/number_types.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace exactvis {

class BoundedDouble {
 public:
  BoundedDouble() noexcept : BoundedDouble(0.0) {}
  // An exact double (k = 0: no error).
  BoundedDouble(double x) noexcept : v_(x), m_(std::fabs(x)), k_(0) {}  // NOLINT: implicit, like a double
  // A value known only by an enclosure [lo, hi] (a point interval is exact): v = lo, k = 10 and a magnitude
  // large enough to cover the width (2^50 (hi - lo) at least), so a narrow enclosure (those of
  // enclosing_interval and CGAL::to_interval are 1-2 ulps wide) costs little and a wide one certifies
  // only values far from 0.
  BoundedDouble(const Interval& i) noexcept : BoundedDouble(i.inf(), i.sup()) {}  // NOLINT
  BoundedDouble(const std::pair<double, double>& e) noexcept : BoundedDouble(e.first, e.second) {}  // NOLINT

  // Two exact operands that cancel exactly (equal coordinates: axis-parallel and shared-vertex
  // configurations) give an exact 0 (magnitude 0), so that products with it are exact zeros too.
  friend BoundedDouble operator+(const BoundedDouble& a, const BoundedDouble& b) noexcept {
    if (((a.k_ | b.k_) == 0) && a.v_ == -b.v_) [[unlikely]]
      return {0.0, 0.0, 0};
    return {a.v_ + b.v_, a.m_ + b.m_, std::max(a.k_, b.k_) + 1};
  }
  friend BoundedDouble operator-(const BoundedDouble& a, const BoundedDouble& b) noexcept {
    if (((a.k_ | b.k_) == 0) && a.v_ == b.v_) [[unlikely]]
      return {0.0, 0.0, 0};
    return {a.v_ - b.v_, a.m_ + b.m_, std::max(a.k_, b.k_) + 1};
  }
  friend BoundedDouble operator-(const BoundedDouble& a) noexcept { return {-a.v_, a.m_, a.k_}; }
  friend BoundedDouble operator*(const BoundedDouble& a, const BoundedDouble& b) noexcept {
    const double m = a.m_ * b.m_;
    // The relative rounding model needs the product of the magnitudes in the normal range; an exact zero
    // factor (m == 0 means the value is exactly 0) gives an exact zero product.
    const bool modelled = (m > std::numeric_limits<double>::min()) | (a.m_ == 0) | (b.m_ == 0);
    return {a.v_ * b.v_, modelled ? m : std::numeric_limits<double>::infinity(), a.k_ + b.k_ + 1};
  }
  BoundedDouble& operator+=(const BoundedDouble& b) noexcept { return *this = *this + b; }
  BoundedDouble& operator-=(const BoundedDouble& b) noexcept { return *this = *this - b; }
  BoundedDouble& operator*=(const BoundedDouble& b) noexcept { return *this = *this * b; }

  // The exact sign of the represented value if the bound proves it, else nullopt.
  std::optional<Sign> certified_sign() const noexcept {
    if (m_ == 0) return Sign::Zero;
    if (k_ > kMaxIndex) return std::nullopt;
    // bound >= g(k) * m: k * kPerIndex is exact, the product rounds down by at most a factor (1 - u) or, in
    // the subnormal range, by at most half the smallest subnormal, which the added denorm_min covers.
    const double bound = static_cast<double>(k_) * kPerIndex * m_ + std::numeric_limits<double>::denorm_min();
    if (v_ > bound) return Sign::Positive;
    if (v_ < -bound) return Sign::Negative;
    return std::nullopt;
  }

  double value() const noexcept { return v_; }
  double magnitude() const noexcept { return m_; }
  int index() const noexcept { return k_; }

 private:
  static constexpr int kMaxIndex = 1 << 20;
  static constexpr double kPerIndex = 0x1p-53 + 0x1p-83;  // u (1 + 2^-30): k * kPerIndex * (1 - u) >= g(k)
  static constexpr int kEnclosureIndex = 10;              // a non-point enclosure

  BoundedDouble(double v, double m, int k) noexcept : v_(v), m_(m), k_(k) {}
  // |x - lo| <= hi - lo <= fl(hi - lo) / (1 - u) <= 8u (1 + 2u) m <= g(10) m when m >= fl(hi - lo) 2^50
  // (exact scaling; an overflow makes m infinite: such wide enclosures certify nothing).
  BoundedDouble(double lo, double hi) noexcept : v_(lo), m_(std::fabs(lo)), k_(0) {
    if (lo == hi) [[likely]]
      return;
    m_ = std::max(std::max(m_, std::fabs(hi)), (hi - lo) * 0x1p50);
    k_ = kEnclosureIndex;
  }

  double v_;  // computed value
  double m_;  // magnitude: |v_| <= m_
  int k_;     // index: |v_ - exact| <= g(k_) m_
};

}  // namespace exactvis
