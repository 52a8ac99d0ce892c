#pragma once
// The one filtering wrapper every predicate of exactvis goes through: three layers, each counted
// (docs/theory.md section 1).
//
// Layer 1 (semi-static filter): the expression in plain double arithmetic in the default rounding mode
//   with an error bound (BoundedDouble, or a hand-written filter of kernel/semi_static_filters.hpp for the
//   hottest predicates); if |value| exceeds the bound, its sign is the exact sign. No rounding-mode switch.
// Layer 2 (interval filter): the expression in interval arithmetic under CGAL::Protect_FPU_rounding; if the
//   interval excludes 0, or is exactly [0,0], its sign is the exact sign.
// Layer 3 (exact): otherwise the same expression is evaluated exactly (GMP rationals, or CGAL::Mpzf).
// (Symbolic perturbation is not used: degenerate configurations are decided exactly and handled by
//  documented rules, see docs/theory.md.)
//
// A predicate is written once as a generic lambda `[&](auto nt) { using NT = typename decltype(nt)::type; ... }`
// (sums, differences and products only; NT is BoundedDouble, Interval or the exact type) and passed to
// filtered_sign; each predicate owns a PredicateCounter (kernel/predicate_counters.hpp).
#include "kernel/bounded_double.hpp"
#include "kernel/number_types.hpp"
#include "kernel/predicate_counters.hpp"
#include "kernel/semi_static_filters.hpp"

#include <atomic>
#include <optional>
#include <type_traits>

namespace exactvis {

namespace detail {
extern std::atomic<bool> filter_enabled_flag;
}

// Global switch for benchmarks and tests: when false, filtered_sign skips layers 1 and 2 (always exact).
void set_filter_enabled(bool enabled);
inline bool filter_enabled() { return detail::filter_enabled_flag.load(std::memory_order_relaxed); }

template <class T>
struct NumberTag {
  using type = T;
};

namespace detail {
// Layer 2, out of line: it is the cold path on generic inputs.
template <class Expr>
[[gnu::noinline]] std::optional<Sign> interval_sign(Expr& expr) {
  CGAL::Protect_FPU_rounding<true> guard;
  const Interval r = expr(NumberTag<Interval>{});
  if (r.inf() > 0) return Sign::Positive;
  if (r.sup() < 0) return Sign::Negative;
  if (r.inf() == 0 && r.sup() == 0) return Sign::Zero;
  return std::nullopt;
}
template <class ExactNT, class Expr>
[[gnu::noinline]] Sign exact_sign_of(Expr& expr) {
  const ExactNT e = expr(NumberTag<ExactNT>{});
  return sign_of(static_cast<int>(CGAL::sign(e)));
}
}  // namespace detail

// The exact sign of expr, through the three layers; `semi_static()` is layer 1 (returns the sign if it can
// certify it, else nullopt). ExactNT is the number type of layer 3: Exact (GMP rationals) by default. A
// division-free predicate whose inputs are all doubles may pass CGAL::Mpzf (exact multiprecision floats,
// CGAL/Mpzf.h), which computes the same exact value several times faster (docs/performance.md).
template <class ExactNT = Exact, class SemiStatic, class Expr>
[[gnu::always_inline]] inline Sign filtered_sign_with(PredicateCounter& counter, SemiStatic&& semi_static,
                                                   Expr&& expr) {
  std::atomic<std::uint64_t>* counts = counter.thread_counts();
  detail::bump(counts[0]);
  if (filter_enabled()) [[likely]] {
    if (const std::optional<Sign> s = semi_static()) {
      detail::bump(counts[1 + static_cast<int>(FilterLayer::SemiStatic)]);
      return *s;
    }
    if (const std::optional<Sign> s = detail::interval_sign(expr)) {
      detail::bump(counts[1 + static_cast<int>(FilterLayer::Interval)]);
      return *s;
    }
  }
  detail::bump(counts[1 + static_cast<int>(FilterLayer::Exact)]);
  return detail::exact_sign_of<ExactNT>(expr);
}

// filtered_sign_with whose layer 1 is the expression itself evaluated in BoundedDouble.
template <class ExactNT = Exact, class Expr>
[[gnu::always_inline]] inline Sign filtered_sign(PredicateCounter& counter, Expr&& expr) {
  return filtered_sign_with<ExactNT>(
      counter, [&] { return expr(NumberTag<BoundedDouble>{}).certified_sign(); }, expr);
}

// Conversion of an input value to the number type a predicate is evaluated in.
template <class NT>
NT as(double v) { return NT(v); }
template <class NT>
NT as(const Exact& v) {
  if constexpr (std::is_same_v<NT, Exact>) return v;
  else return NT(enclosing_interval(v));
}

}  // namespace exactvis
