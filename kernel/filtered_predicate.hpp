#pragma once
// The one filtering wrapper every predicate of exactvis goes through.
//
// Layer 1 (filter): the predicate's expression is evaluated in interval arithmetic from the exact inputs;
//   if the interval excludes 0, or is exactly [0,0], its sign is the exact sign.
// Layer 2 (exact): otherwise the same expression is evaluated with exact rationals (GMP).
// (Layer 3, symbolic perturbation, is not used: degenerate configurations are decided exactly and handled
//  by documented rules, see docs/theory.md.)
//
// A predicate is written once as a generic lambda `[&](auto nt) { using NT = typename decltype(nt)::type; ... }`
// and passed to filtered_sign. Each predicate owns a PredicateCounter that counts calls and exact fallbacks.
#include "kernel/number_types.hpp"

#include <atomic>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace exactvis {

// Calls and exact fallbacks of one predicate. The counts are striped over a few cache lines, one per thread
// slot, so that threads evaluating the same predicate do not fight over one shared counter.
struct PredicateCounter {
  static constexpr unsigned kSlots = 8;
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> calls{0};
    std::atomic<std::uint64_t> exact{0};  // evaluations where the filter could not decide
  };
  std::string name;
  Slot slots[kSlots];
  explicit PredicateCounter(std::string n);
  Slot& mine() { return slots[thread_slot()]; }
  std::uint64_t calls() const;
  std::uint64_t exact() const;
  void reset();
  static unsigned thread_slot();
};

struct PredicateCounterSnapshot {
  std::string name;
  std::uint64_t calls = 0;
  std::uint64_t exact = 0;
};

// All counters registered so far, one entry per predicate name (counters sharing a name are summed), and
// resetting them (for tests and benchmarks).
std::vector<PredicateCounterSnapshot> predicate_counters();
void reset_predicate_counters();
// Total exact-path evaluations over all predicates.
std::uint64_t exact_evaluations_total();

// Global switch for benchmarks and tests: when false, filtered_sign skips layer 1 (always exact).
void set_filter_enabled(bool enabled);
bool filter_enabled();

template <class T>
struct NumberTag {
  using type = T;
};

// ExactNT is the number type of layer 2: Exact (GMP rationals) by default. A division-free predicate whose
// inputs are all doubles may pass CGAL::Mpzf (exact multiprecision floats, CGAL/Mpzf.h), which computes the
// same exact value several times faster (see docs/performance.md, "Predicates").
template <class ExactNT = Exact, class Expr>
Sign filtered_sign(PredicateCounter& counter, Expr&& expr) {
  PredicateCounter::Slot& slot = counter.mine();
  slot.calls.fetch_add(1, std::memory_order_relaxed);
  if (filter_enabled()) {
    CGAL::Protect_FPU_rounding<true> guard;
    const Interval r = expr(NumberTag<Interval>{});
    if (r.inf() > 0) return Sign::Positive;
    if (r.sup() < 0) return Sign::Negative;
    if (r.inf() == 0 && r.sup() == 0) return Sign::Zero;
  }
  slot.exact.fetch_add(1, std::memory_order_relaxed);
  const ExactNT e = expr(NumberTag<ExactNT>{});
  return sign_of(static_cast<int>(CGAL::sign(e)));
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
